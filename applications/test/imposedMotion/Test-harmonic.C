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
    flapFoamTest-imposedMotion: imposedMotions::harmonic, q = offset
    + A cos(2 pi f t + phase): derivatives against finite differences,
    closed-form values.

\*---------------------------------------------------------------------------*/

#include "imposedMotionTests.H"

// * * * * * * * * * * * * * * * * harmonic  * * * * * * * * * * * * * * * * //

TEST(Harmonic, DerivativesMatchFiniteDifferences)
{
    auto m = makeMotion
    (
        "type harmonic; joint 0; amplitude 0.9948; frequency 2;"
        " phase 0.3; offset -0.9948;"
    );
    checkDerivatives(*m, 0, 0.5);
}


TEST(Harmonic, ClosedFormValues)
{
    const scalar A = 0.9948, f = 2, q0 = -0.25, w = twoPi*f;
    auto m = makeMotion
    (
        "type harmonic; joint 4; amplitude 0.9948; frequency 2; offset -0.25;"
    );

    EXPECT_EQ(m->type(), "harmonic");
    ASSERT_EQ(m->joints().size(), 1);
    EXPECT_EQ(m->joints()[0], 4);

    // t = 0: q = offset + A, qDot = 0, qDdot = -A w^2
    const jointState s0 = eval(*m, 0, 0);
    EXPECT_NEAR(s0.q, q0 + A, 1e-15);
    EXPECT_NEAR(s0.qDot, 0, 1e-15);
    EXPECT_NEAR(s0.qDdot, -A*w*w, 1e-12*A*w*w);

    // t = T/4: q = offset, qDot = -A w, qDdot = 0
    const jointState s1 = eval(*m, 0, 0.25/f);
    EXPECT_NEAR(s1.q, q0, 1e-14);
    EXPECT_NEAR(s1.qDot, -A*w, 1e-12*A*w);
    EXPECT_NEAR(s1.qDdot, 0, 1e-12*A*w*w);

    // Phase: q(t) = offset + A cos(w t + phase)
    auto mp = makeMotion
    (
        "type harmonic; joint 0; amplitude 2; frequency 3; phase 0.5;"
    );
    EXPECT_NEAR(eval(*mp, 0, 0.1).q, 2*std::cos(twoPi*3*0.1 + 0.5), 1e-14);
}


// ************************************************************************* //
