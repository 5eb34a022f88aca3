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
    Tests of Foam::holeFlood (the flood fill of the octreeInverseDistance
    stencil: the stock findHoles' result) on a block of 8^3 hexahedra whose
    faces at x = 0 are a wall and the other boundary faces an overset patch:

      - a cube of cells enclosed by a shell of holes (no patch face) is
        made holes; the cells outside (reached from the wall) are not;
      - a slab of holes cuts the block in two: the half away from the wall
        is made holes when its overset-patch cells have no donors, and kept
        when they have donors in the half that touches the wall (reached
        through interpolation), or in the enclosed cube that is itself not
        reached (made holes with it: the rule of the stock);
      - no hole: nothing changes, one round.

    Every test asserts; the program exits non-zero on failure.

\*---------------------------------------------------------------------------*/

#include "holeFlood.H"
#include "cellCellStencil.H"
#include "wallPolyPatch.H"
#include "oversetPolyPatch.H"
#include "scratchTime.H"
#include "oversetTestMeshes.H"

#include <gtest/gtest.h>

#include <memory>

using namespace Foam;
using namespace oversetTest;

namespace
{

const label n = 8;
const label C = cellCellStencil::CALCULATED;
const label H = cellCellStencil::HOLE;

//- The cell (i, j, k) of hexBlock's numbering
label cellAt(const label i, const label j, const label k)
{
    return i + n*(j + n*k);
}


//- The n^3 block as an fvMesh: faces at x = 0 a wall, the rest overset
std::unique_ptr<fvMesh> floodBlock(const Time& runTime)
{
    const auto block = hexBlock(runTime, "floodBlockCells", n, 0);
    const label nInternal = block->nInternalFaces();
    const label nFaces = block->nFaces();

    // Internal faces, then the wall's, then the overset patch's
    labelList order(identity(nInternal));
    order.setSize(nFaces);
    label nWall = 0;
    label next = nInternal;
    for (label pass = 0; pass < 2; ++pass)
    {
        for (label facei = nInternal; facei < nFaces; ++facei)
        {
            const bool wall = block->faceCentres()[facei].x() < 1e-9;
            if (wall == (pass == 0))
            {
                order[next++] = facei;
                nWall += wall;
            }
        }
    }

    auto mesh = std::unique_ptr<fvMesh>
    (
        new fvMesh
        (
            IOobject
            (
                "floodBlock",
                runTime.constant(),
                runTime,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            pointField(block->points()),
            faceList(UIndirectList<face>(block->faces(), order)),
            labelList(UIndirectList<label>(block->faceOwner(), order)),
            labelList(block->faceNeighbour())
        )
    );
    List<polyPatch*> patches(2);
    patches[0] = new wallPolyPatch
    (
        "wall", nWall, nInternal, 0, mesh->boundaryMesh(),
        wallPolyPatch::typeName
    );
    patches[1] = new oversetPolyPatch
    (
        "overset", nFaces - nInternal - nWall, nInternal + nWall, 1,
        mesh->boundaryMesh(), oversetPolyPatch::typeName
    );
    mesh->addFvPatches(patches);
    return mesh;
}


//- Cells with i in [2, 5] and j, k in [2, 5]: the shell (any index 2 or
//- 5) holes, the inner 2^3 cube calculated; the slab i = 6 holes
labelList shellAndSlab(const bool slab)
{
    labelList types(n*n*n, C);
    for (label k = 2; k <= 5; ++k)
    {
        for (label j = 2; j <= 5; ++j)
        {
            for (label i = 2; i <= 5; ++i)
            {
                const bool inner =
                    i > 2 && i < 5 && j > 2 && j < 5 && k > 2 && k < 5;
                types[cellAt(i, j, k)] = inner ? C : H;
            }
        }
    }
    if (slab)
    {
        for (label k = 0; k < n; ++k)
        {
            for (label j = 0; j < n; ++j)
            {
                types[cellAt(6, j, k)] = H;
            }
        }
    }
    return types;
}


//- Each overset-patch cell of the far half (i = 7) given the donor donor
labelListList farDonors(const fvMesh& mesh, const label donor)
{
    labelListList stencil(mesh.nCells());
    for (const label celli : mesh.boundary()["overset"].faceCells())
    {
        if (celli % n == 7 && donor >= 0)
        {
            stencil[celli] = labelList(1, donor);
        }
    }
    return stencil;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(holeFlood, enclosedCellsAndUnreachedHalf)
{
    scratchTime time("flapFoamTest-holeFlood", 1, 1);
    const auto mesh = floodBlock(time());
    const globalIndex globalCells(mesh->nCells());
    holeFlood flood(*mesh);

    // The enclosed cube only: its 8 cells become holes
    {
        labelList types(shellAndSlab(false));
        const labelList before(types);
        const holeFlood::counts c =
            flood.apply(globalCells, labelListList(mesh->nCells()), types);
        EXPECT_EQ(c.holes, 8);
        forAll(types, celli)
        {
            const label i = celli % n;
            const label j = (celli/n) % n;
            const label k = celli/(n*n);
            const bool inner =
                i > 2 && i < 5 && j > 2 && j < 5 && k > 2 && k < 5;
            EXPECT_EQ(types[celli], inner ? H : before[celli])
                << "cell " << celli;
        }
    }

    // With the slab: the far half (i = 7, 64 cells) too, without donors
    {
        labelList types(shellAndSlab(true));
        const holeFlood::counts c =
            flood.apply(globalCells, farDonors(*mesh, -1), types);
        EXPECT_EQ(c.holes, 8 + 64);
        EXPECT_EQ(types[cellAt(7, 0, 0)], H);
        EXPECT_EQ(types[cellAt(0, 0, 0)], C);
    }

    // Donors in the near half: reached through interpolation
    {
        labelList types(shellAndSlab(true));
        const holeFlood::counts c =
            flood.apply(globalCells, farDonors(*mesh, cellAt(1, 1, 1)), types);
        EXPECT_EQ(c.holes, 8);
        EXPECT_EQ(types[cellAt(7, 0, 0)], C);
        EXPECT_EQ(c.rounds, 2);
    }

    // Donors in the enclosed cube, itself not reached: holes as well
    {
        labelList types(shellAndSlab(true));
        const holeFlood::counts c =
            flood.apply(globalCells, farDonors(*mesh, cellAt(3, 3, 3)), types);
        EXPECT_EQ(c.holes, 8 + 64);
    }
}


TEST(holeFlood, noHoleNoChange)
{
    scratchTime time("flapFoamTest-holeFlood", 1, 1);
    const auto mesh = floodBlock(time());
    holeFlood flood(*mesh);
    labelList types(mesh->nCells(), C);
    const holeFlood::counts c = flood.apply
    (
        globalIndex(mesh->nCells()),
        labelListList(mesh->nCells()),
        types
    );
    EXPECT_EQ(c.holes, 0);
    EXPECT_EQ(c.regions, 1);
    EXPECT_EQ(c.rounds, 1);
    EXPECT_EQ(types, labelList(mesh->nCells(), C));
}


// ************************************************************************* //
