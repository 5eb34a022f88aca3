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
    flapFoamTest-imposedMotion

Description
    GoogleTest unit tests of libflapFoamImposedMotion, one file per class
    (Test-<class>.C, helpers in imposedMotionTests.H):
      - every motion type: the exact qDot, qDdot against central finite
        differences of q, qDot over two periods (negative times included),
        and closed-form values (extrema, zero crossings, limits in K);
      - tabulated: knots reproduced, periodicity, C2 continuity, convergence
        of the spline of a sine, file input equal to values input, and the
        cyclic tridiagonal solver against its residual;
      - write() then read back gives the same motion (every type, the list);
      - every bad input stops with a FatalIOError whose message names the
        key (FatalError and FatalIOError are made to throw), an unknown key
        (e.g. a misspelled optional one) listing the allowed keys;
      - wangParametrization midStart: the paper authors' q(t) (their
        formulas and their dictionary's numbers), exact derivatives;
      - imposedMotionList: joints ascending, evaluate writes only the
        prescribed entries, empty without the sub-dictionary, the authors'
        spelling ImposedMotion (both spellings: FatalIOError);
      - imposedMotionBlend (run-time parameter changes): q, qDot, qDdot
        continuous across a change, exact derivatives inside the blend, a
        change during a blend, frequency without phase jump, the chain
        bounded, the state round trip bit for bit, bad input.

\*---------------------------------------------------------------------------*/

#include "throwingTestMain.H"


// ************************************************************************* //
