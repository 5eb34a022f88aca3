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
    Unit tests of couplingGraph on the box of couplingsBox.H.

\*---------------------------------------------------------------------------*/

#include "couplingsBox.H"
#include "couplingGraph.H"

#include <map>

using namespace couplingsBox;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The row of a cell: neighbour -> weight
std::map<label, label> row(const couplingGraph& g, const label celli)
{
    std::map<label, label> r;
    for (label e = g.xadj()[celli]; e < g.xadj()[celli + 1]; ++e)
    {
        r[g.adjncy()[e]] = g.adjwgt()[e];
    }
    return r;
}


//- Every edge (a, b) has (b, a) of the same weight, none to itself
void expectSymmetric(const couplingGraph& g)
{
    for (label a = 0; a < g.nCells(); ++a)
    {
        for (const auto& nw : row(g, a))
        {
            EXPECT_NE(nw.first, a);
            EXPECT_EQ(row(g, nw.first)[a], nw.second)
                << "edge " << a << " - " << nw.first;
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(couplingGraph, facesOnlyWithoutCouplingWeight)
{
    const box b;
    const couplingGraph g(b.mesh(), *b.couplings(), 0, scalarField());

    // 4 x 3 x 2 cells: 3*3*2 + 4*2*2 + 4*3*1 = 46 internal faces
    ASSERT_EQ(g.nCells(), 24);
    ASSERT_EQ(g.xadj().size(), 25);
    EXPECT_EQ(g.adjncy().size(), 2*46);
    for (const label w : g.adjwgt())
    {
        EXPECT_EQ(w, couplingGraph::faceWeight);
    }
    const std::map<label, label> corner
    {
        {cellID(1, 0, 0), 64}, {cellID(0, 1, 0), 64}, {cellID(0, 0, 1), 64}
    };
    EXPECT_EQ(row(g, 0), corner);
    expectSymmetric(g);
    EXPECT_EQ(g.cellWeight(), labelList(24, 1));
}


TEST(couplingGraph, couplingEdgesWeighTheirShareOfThePoses)
{
    const box b;
    const couplingGraph g(b.mesh(), *b.couplings(), 1, scalarField());

    // (0, 23) in both poses: a face's 64; (0, 1) in one of two: 32 added
    // to the face; (5, 18) in one: 32
    const std::map<label, label> corner
    {
        {1, 64 + 32}, {cellID(0, 1, 0), 64}, {cellID(0, 0, 1), 64}, {23, 64}
    };
    EXPECT_EQ(row(g, 0), corner);
    EXPECT_EQ(row(g, 23)[0], 64);
    EXPECT_EQ(row(g, 5)[18], 32);
    EXPECT_EQ(g.adjncy().size(), 2*46 + 2*2);
    expectSymmetric(g);

    // A weight below one rounds up to 1: 64 x 0.01 x 1/2 = 0.32
    const couplingGraph light(b.mesh(), *b.couplings(), 0.01, scalarField());
    EXPECT_EQ(row(light, 0)[1], 64 + 1);
    EXPECT_EQ(row(light, 0)[23], 1);
}


TEST(couplingGraph, oversetWorkAndTheKeptPoses)
{
    const box b;
    const couplingGraph g(b.mesh(), *b.couplings(), 1, scalarField());

    labelList work(24, Zero);
    work[0] = 2; work[12] = 2; work[23] = 2;
    work[1] = 1; work[5] = 1; work[18] = 1;
    EXPECT_EQ(g.oversetWork(), work);

    ASSERT_EQ(g.nPoses(), 2);
    ASSERT_EQ(g.poseWork().size(), 2);
    labelList pose0(24, Zero), pose1(24, Zero);
    for (const label c : {0, 1, 5, 18, 23}) pose0[c] = 1;
    for (const label c : {0, 23}) pose1[c] = 1;
    EXPECT_EQ(g.poseWork()[0], pose0);
    EXPECT_EQ(g.poseWork()[1], pose1);
}


TEST(couplingGraph, cellWeightsRelativeToTheSmallest)
{
    const box b;
    scalarField weights(24, 2.0);
    weights[3] = 5.0;       // 2.5 times the smallest: rounds to 3
    const couplingGraph g(b.mesh(), *b.couplings(), 1, weights);
    labelList expected(24, 1);
    expected[3] = 3;
    EXPECT_EQ(g.cellWeight(), expected);
}


TEST(couplingGraph, badInput)
{
    const box b;
    expectError
    (
        [&]{ couplingGraph(b.mesh(), *b.couplings(), 1, scalarField(5, 1)); },
        {"5 cell weights", "one positive weight per cell (24)"}
    );
    scalarField negative(24, 1.0);
    negative[7] = -1;
    expectError
    (
        [&]{ couplingGraph(b.mesh(), *b.couplings(), 1, negative); },
        {"smallest -1", "one positive weight per cell (24)"}
    );
    expectIOError
    (
        [&]{ b.couplings(30); },
        {"nCells 24", "the couplings of another mesh", "has 30 cells"}
    );
    const box inconsistent(10);
    expectIOError
    (
        [&]{ inconsistent.couplings(); },
        {"nCells 10 but acceptorPoses lists 24 cells"}
    );
}


// ************************************************************************* //
