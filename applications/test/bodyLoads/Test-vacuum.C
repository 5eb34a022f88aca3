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
    Tests of bodyLoads::vacuum: exactly zero on every body, with a flow
    present (bodyLoad vacuum or fluidLoad off) or with no mesh at all (the
    registry a Time).

\*---------------------------------------------------------------------------*/

#include "boxLoadsCase.H"

using namespace boxLoadsCase;

// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(vacuum, zeroInAFlow)
{
    flowCase flow(sqr(dimVelocity), 3.7);
    flow.setLinearU();
    flow.addTransport();

    // The flow loads the plate and the lid
    const Field<spatialVector> fluid(flow.loads());
    EXPECT_GT(mag(fluid[1]), 1);
    EXPECT_GT(mag(fluid[3]), 1);

    for (const std::string keys : {"bodyLoad vacuum;", "fluidLoad off;"})
    {
        SCOPED_TRACE(keys);
        const Field<spatialVector> fx(flow.loads(keys));
        ASSERT_EQ(fx.size(), 4);
        for (const spatialVector& f : fx)
        {
            EXPECT_TRUE(f == spatialVector::zero) << str(f);
        }
    }
}


TEST(vacuum, zeroWithoutAMesh)
{
    scratchTime time("flapFoamTest-bodyLoads", 1, 1);
    const Field<spatialVector> fx
    (
        loadsOf(time(), time(), modelDict("fluidLoad off;"))
    );

    ASSERT_EQ(fx.size(), 4);
    for (const spatialVector& f : fx)
    {
        EXPECT_TRUE(f == spatialVector::zero) << str(f);
    }
}


// ************************************************************************* //
