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
    flapFoamTest-oversetDecomp

Description
    GoogleTest unit tests of libflapFoamOversetDecomp (Test-<class>.C) on
    the 4 x 3 x 2 box of applications/test/include/boxMesh.H and a
    couplings file written by hand (couplingsBox.H):
      - couplingGraph: the faces' edges (weight 64, both directions), the
        couplings' edges (64 couplingWeight f, f the fraction of the poses,
        at least 1, added to a face's), the cell weights, the overset work
        and the work of each kept pose; bad cell weights and the couplings
        of another mesh stop with an error naming them;
      - graphPartitioner: METIS and Scotch give every cell a part, parts
        balanced within the allowed imbalance, and keep a heavily coupled
        pair of opposite corners together; a bad partitioner is refused.
    The scenarios of whole decompositions (decomposePar, serial against
    parallel) are applications/test/oversetDecomp/Alltest.

\*---------------------------------------------------------------------------*/

#include "throwingTestMain.H"


// ************************************************************************* //
