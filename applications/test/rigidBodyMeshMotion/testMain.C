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

Application
    flapFoamTest-rigidBodyMeshMotion

Description
    GoogleTest unit tests of libflapFoamRigidBodyMeshMotion
    (Test-<class>.C) on the box mesh of applications/test/include/boxMesh.H
    split into two cell zones (wing: the cells of x index >= 2; background:
    the others), in vacuum:
      - eABAMeshMotion: a free fall on a slider moves the wing zone by
        -g t^2/2 (Newmark, exact for a constant acceleration), the
        background with it in the components it follows and not in the
        others; a rotation at constant rate turns the wing zone rigidly
        about the joint's axis; bad background entries stop with a
        FatalIOError naming them.

\*---------------------------------------------------------------------------*/

#include "throwingTestMain.H"


// ************************************************************************* //
