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
    Tests of Foam::patchVoxelExchange in a serial run (one rank: nothing
    to send): the received maps are cleared into the local maps' grids
    every step, and nothing is sent; the selection by block (a block whose
    box misses every box skipped whole) selects exactly the voxels that
    the voxel-by-voxel selection does, on random maps and boxes, boxes
    touching block faces included, while testing fewer one by one.  The
    parallel exchange is tested end to end by compareMotion -np 2 (the same
    holes and stencil checksums as serial).

\*---------------------------------------------------------------------------*/

#include "patchVoxelExchange.H"
#include "Random.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(patchVoxelExchange, serialReceivesNothingInTheLocalGrids)
{
    List<patchVoxelMap> local(2);
    local[0].reset(boundBox(point::zero, point::one), labelVector(5, 6, 7));
    local[1].reset(boundBox(point(1, 1, 1), point(2, 3, 4)), labelVector(3, 3, 3));
    local[0].fillPatchFace(boundBox(point::zero, point(0.5, 0.5, 0.5)));
    List<patchVoxelMap::blockedVoxels> voxels(2);
    voxels[0] = local[0].patchVoxelBlocks();
    ASSERT_FALSE(voxels[0].voxels.empty());

    patchVoxelExchange exchange;
    exchange.clear(2);
    for (label step = 0; step < 2; ++step)
    {
        exchange.exchange
        (
            local, voxels, List<List<treeBoundBoxList>>(Pstream::nProcs())
        );
        EXPECT_EQ(exchange.nSent(), 0);
        forAll(local, zonei)
        {
            const patchVoxelMap& remote = exchange.remote(zonei);
            EXPECT_TRUE(remote.noPatch());
            EXPECT_TRUE(remote.allOther());
            EXPECT_EQ(remote.nDivs(), local[zonei].nDivs());
            EXPECT_TRUE(remote.bb() == local[zonei].bb());
        }
    }

    // No zones
    exchange.clear(0);
    exchange.exchange
    (
        List<patchVoxelMap>(), List<patchVoxelMap::blockedVoxels>(),
        List<List<treeBoundBoxList>>(Pstream::nProcs())
    );
    EXPECT_EQ(exchange.nSent(), 0);
}


TEST(patchVoxelExchange, blocksSelectTheVoxelsOfTheVoxelTest)
{
    // A map of random face boxes (many blocks), and random target boxes,
    // some with a face on a block face: the same voxels either way
    const boundBox bb(point(-1, 0, 0), point(1, 0.5, 2));
    const labelVector n(37, 19, 41);
    List<patchVoxelMap> local(1);
    local[0].reset(bb, n);
    Random rnd(7);
    for (label i = 0; i < 60; ++i)
    {
        const point lo(bb.min() + cmptMultiply(rnd.sample01<vector>(), bb.span()));
        local[0].fillPatchFace
        (
            boundBox(lo, lo + 0.05*cmptMultiply(rnd.sample01<vector>(), bb.span()))
        );
    }
    labelListList flat(1, local[0].patchVoxels());
    List<patchVoxelMap::blockedVoxels> blocked(1, local[0].patchVoxelBlocks());
    ASSERT_GT(blocked[0].blocks.size(), 10);
    EXPECT_EQ(blocked[0].starts.last(), flat[0].size());

    patchVoxelExchange exchange;
    label selected = 0;
    for (label trial = 0; trial < 40; ++trial)
    {
        List<treeBoundBoxList> tgt(1);
        const point lo(bb.min() + cmptMultiply(rnd.sample01<vector>(), bb.span()));
        treeBoundBox box(lo, lo + 0.3*cmptMultiply(rnd.sample01<vector>(), bb.span()));
        if (trial % 4 == 0)
        {
            // Its upper x face on a block face (8 voxels of 2/37)
            box.max().x() = bb.min().x() + 8*(trial/4 % 4 + 1)*bb.span().x()/n.x();
        }
        tgt[0].append(box);

        exchange.clear(1);
        labelList byVoxel(exchange.select(local, flat, tgt)[0]);
        const label nByVoxel = exchange.nScanned();
        exchange.clear(1);
        labelList byBlock(exchange.select(local, blocked, tgt)[0]);
        Foam::sort(byBlock);
        EXPECT_EQ(byBlock, byVoxel) << "trial " << trial;
        EXPECT_LE(exchange.nScanned(), nByVoxel);
        selected += byVoxel.size();
    }
    EXPECT_GT(selected, 0);
}


// ************************************************************************* //
