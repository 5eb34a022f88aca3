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

Application
    flapFoamTest-decompose

Description
    GoogleTest unit tests of libmetisDecomp and libscotchDecomp (OpenFOAM
    v1912's own decomposition methods built against Debian's METIS and
    Scotch, src/decompose): selected by name from decompositionMethod's
    run-time table, they cut the 4 x 3 x 2 box of boxMesh.H into 2, 3
    and 4 parts, every cell in a part, no part empty, balanced within a
    cell, the same parts again, and cell weights move the cut (Debian's
    dummy stubs stop with "not compiled").  Whole decompositions of the
    drone cases with decomposePar: applications/test/decompose/Alltest.

\*---------------------------------------------------------------------------*/

#include "boxMesh.H"
#include "scratchTime.H"
#include "decompositionMethod.H"
#include "IStringStream.H"
#include "partSizes.H"
#include "throwingTestMain.H"

using namespace boxCase;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The parts of the box's cells by method into n parts, cell weights w
labelList parts(const word& method, const label n, const scalarField& w)
{
    scratchTime time("flapFoamTest-decompose", 1, 1);
    const std::unique_ptr<polyMesh> mesh(boxShapes(time()));
    dictionary dict;
    dict.add("numberOfSubdomains", n);
    dict.add("method", method);
    return decompositionMethod::New(dict)->decompose
    (
        *mesh, mesh->cellCentres(), w
    );
}


const wordList methods({"metis", "scotch"});

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(decompose, balancedPartsOfEveryCell)
{
    for (const word& method : methods)
    {
        for (const label n : {2, 3, 4})
        {
            const labelList part(parts(method, n, scalarField()));
            ASSERT_EQ(part.size(), 24) << method;
            const labelList count(partSizes(part, n));
            EXPECT_GT(min(count), 0) << method << " " << text(count);
            EXPECT_LE(max(count) - min(count), 1)
                << method << " " << n << " parts: " << text(count);
            EXPECT_EQ(parts(method, n, scalarField()), part)
                << method << ": another decomposition the second time";
        }
    }
}


TEST(decompose, cellWeightsMoveTheCut)
{
    // The three cells of the x = 0 column of the lower layer weigh 5:
    // their part gets fewer cells
    scalarField w(24, 1.0);
    for (const label j : {0, 1, 2})
    {
        w[4*j] = 5;
    }
    for (const word& method : methods)
    {
        const labelList part(parts(method, 2, w));
        const labelList count(partSizes(part, 2));
        scalarField load(2, Zero);
        forAll(part, celli)
        {
            load[part[celli]] += w[celli];
        }
        EXPECT_NE(count[0], count[1]) << method << " " << text(count);
        // 36 of weight in all: each part within 3 of 18
        EXPECT_LE(mag(load[0] - load[1]), 6) << method;
    }
}


// ************************************************************************* //
