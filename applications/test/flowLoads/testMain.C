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
    flapFoamTest-flowLoads

Description
    GoogleTest unit tests of libflapFoamFlowLoads (Test-<class>.C) on the
    box case of applications/test/include/boxLoadsCase.H, whose sides are
    the bodies' patches:
      - patchLoad: uniform pressure and the wall shear of a linear velocity
        against the analytic force and moment (round-off), for a kinematic
        p (rhoInf) and p in Pa (rho field), with the laminar transport
        alone and with a laminar turbulence model; bodies without patches
        get zero; every bad input stops with an error naming it.

\*---------------------------------------------------------------------------*/

#include "throwingTestMain.H"


// ************************************************************************* //
