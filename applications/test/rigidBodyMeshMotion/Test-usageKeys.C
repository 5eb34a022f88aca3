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
    flapFoamTest-rigidBodyMeshMotion: the Usage tables of eABAMeshMotion.H
    and of the headers whose keys it takes (eABAMotion, bodyLoad,
    patchLoad, aerodynamics) against eABAMeshMotion's allowed keys, at the
    top level of dynamicMeshDict and in background (usageKeys.H).

\*---------------------------------------------------------------------------*/

#include "eABAMeshMotion.H"
#include "usageKeys.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(usageKeys, eABAMeshMotion)
{
    const usageKeys documented
    ({
        "rigidBodyMeshMotion/eABAMeshMotion/eABAMeshMotion.H",
        "rigidBodyDynamics/eABAMotion/eABAMotion.H",
        "bodyLoads/bodyLoad/bodyLoad.H",
        "flowLoads/patchLoad/patchLoad.H",
        "bodyLoads/aerodynamics/aerodynamics.H"
    });
    expectUsageKeys(documented, eABAMeshMotion::keys(true));
    expectUsageKeys
    (
        documented, eABAMeshMotion::backgroundKeys(), "background"
    );
}


// ************************************************************************* //
