/*---------------------------------------------------------------------------*\
  flapFoam: free-flight simulation of flapping-wing drones on OpenFOAM v1912
-------------------------------------------------------------------------------
    Copyright (C) 2025-2026 flapFoam developers
-------------------------------------------------------------------------------
License
    This file is part of flapFoam, derived from OpenFOAM.

    flapFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    flapFoam is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with flapFoam (COPYING).  If not, see <http://www.gnu.org/licenses/>.

Description
    Unit tests of graphPartitioner (METIS and Scotch) and of the settings
    that choose it, on the box of couplingsBox.H.

\*---------------------------------------------------------------------------*/

#include "couplingsBox.H"
#include "couplingGraph.H"
#include "graphPartitioner.H"
#include "oversetGraphSettings.H"
#include "IStringStream.H"
#include "partSizes.H"

using namespace couplingsBox;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The settings of an oversetGraphCoeffs text
oversetGraphSettings settings(const std::string& text)
{
    return oversetGraphSettings
    (
        dictionary(IStringStream(text)()), "oversetGraphCoeffs"
    );
}


//- The partitioners: METIS balancing the cells (a graph of 24 cells, the
//- overset work on 6 of them, cannot balance the work too: poseGroups 0,
//- oversetImbalance 10 leave it free), Scotch
const wordList libraries
({
    "metis; poseGroups 0; oversetImbalance 10",
    "scotch"
});

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(graphPartitioner, everyCellInABalancedPart)
{
    const box b;
    const couplingGraph g(b.mesh(), *b.couplings(), 1, scalarField());
    for (const word& lib : libraries)
    {
        const graphPartitioner p
        (
            settings("partitioner " + lib + "; imbalance 0.1;")
        );
        EXPECT_EQ(p.libraryName(), lib.substr(0, lib.find(';')));
        for (const label n : {2, 3, 4})
        {
            const labelList part(p.partition(g, n));
            ASSERT_EQ(part.size(), 24) << lib;
            const labelList sizes(partSizes(part, n));
            // 24/n cells each, within the imbalance 0.1 and one cell
            EXPECT_LE(max(sizes), label(1.1*24/n) + 1) << lib << " " << n
                << " parts: " << text(sizes);
            EXPECT_GT(min(sizes), 0) << lib << " " << n;
        }
        EXPECT_EQ(p.partition(g, 1), labelList(24, Zero)) << lib;
    }
}


TEST(graphPartitioner, aHeavyCouplingKeepsItsCellsTogether)
{
    const box b;
    // Faces only: the cut of two halves is 6 faces; the opposite corners
    // 0 and 23 of a balanced cut along x lie in different halves
    // (coupled at 1000 faces' weight they are kept together)
    const couplingGraph faces(b.mesh(), *b.couplings(), 0, scalarField());
    const couplingGraph heavy(b.mesh(), *b.couplings(), 1000, scalarField());
    for (const word& lib : libraries)
    {
        const graphPartitioner p(settings("partitioner " + lib + ";"));
        const labelList part(p.partition(faces, 2));
        EXPECT_NE(part[0], part[23]) << lib << ": " << text(part);
        const labelList coupled(p.partition(heavy, 2));
        EXPECT_EQ(coupled[0], coupled[23]) << lib << ": " << text(coupled);
        EXPECT_LE(max(partSizes(coupled, 2)), 13) << lib;
    }
}


TEST(graphPartitioner, emptyPartsAreReported)
{
    // METIS under four constraints (cells, the cycle's overset work and
    // each pose's, pose 1's work on two cells alone) into 3 parts of a
    // graph of 24 cells leaves a part empty: a warning says so and what
    // to change
    const box b;
    const couplingGraph g(b.mesh(), *b.couplings(), 1, scalarField());
    const graphPartitioner p(settings("partitioner metis;"));
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    const labelList sizes(partSizes(p.partition(g, 3), 3));
    const std::string out =
        testing::internal::GetCapturedStdout()
      + testing::internal::GetCapturedStderr();
    EXPECT_EQ(min(sizes), 0) << text(sizes);
    EXPECT_NE(out.find("metis left 1 of 3 parts empty"), std::string::npos)
        << out;
    EXPECT_NE(out.find("poseGroups 0"), std::string::npos) << out;

    // Scotch's one combined weight fills every part
    testing::internal::CaptureStdout();
    const graphPartitioner s(settings("partitioner scotch;"));
    EXPECT_GT(min(partSizes(s.partition(g, 3), 3)), 0);
    EXPECT_EQ(testing::internal::GetCapturedStdout().find("parts empty"),
              std::string::npos);
}


TEST(graphPartitioner, badSettings)
{
    expectIOError
    (
        []{ settings("partitioner chaco;"); },
        {"partitioner chaco unknown", "metis", "scotch"}
    );
    expectIOError
    (
        []{ settings("couplingWeight 2000;"); },
        {"couplingWeight", "2000"}
    );
}


// ************************************************************************* //
