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
    flapFoamTest-bodyLoads

Description
    GoogleTest unit tests of libflapFoamBodyLoads, one file per class
    (Test-<class>.C, helpers in bodyLoadsTests.H), on a box mesh whose
    sides are the bodies' patches:
      - patchLoad: uniform pressure and the wall shear of a linear velocity
        against the analytic force and moment (round-off), for a kinematic
        p (rhoInf) and p in Pa (rho field), with the laminar transport
        alone and with a laminar turbulence model; bodies without patches
        get zero; every bad input stops with an error naming it;
      - vacuum (bodyLoad vacuum, fluidLoad off): exactly zero;
      - bodyLoad: the selection by bodyLoad and fluidLoad, an unknown type
        a FatalIOError listing the valid ones, treeBodyID.

\*---------------------------------------------------------------------------*/

#include "throwingTestMain.H"


// ************************************************************************* //
