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
    every step, and nothing is sent.  The parallel exchange is tested end
    to end by compareMotion -np 2 (the same holes and stencil checksums as
    serial).

\*---------------------------------------------------------------------------*/

#include "patchVoxelExchange.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(patchVoxelExchange, serialReceivesNothingInTheLocalGrids)
{
    List<patchVoxelMap> local(2);
    local[0].reset(boundBox(point::zero, point::one), labelVector(5, 6, 7));
    local[1].reset(boundBox(point(1, 1, 1), point(2, 3, 4)), labelVector(3, 3, 3));
    local[0].fillPatchFace(boundBox(point::zero, point(0.5, 0.5, 0.5)));
    labelListList voxels(2);
    voxels[0] = local[0].patchVoxels();
    ASSERT_FALSE(voxels[0].empty());

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
        List<patchVoxelMap>(), labelListList(),
        List<List<treeBoundBoxList>>(Pstream::nProcs())
    );
    EXPECT_EQ(exchange.nSent(), 0);
}


// ************************************************************************* //
