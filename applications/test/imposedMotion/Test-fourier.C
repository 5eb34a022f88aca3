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
    flapFoamTest-imposedMotion: imposedMotions::fourier: derivatives against
    finite differences, the direct sum of the series, one coefficient list
    alone; bad coefficient lists are FatalIOErrors.

\*---------------------------------------------------------------------------*/

#include "imposedMotionTests.H"

// * * * * * * * * * * * * * * * * * fourier * * * * * * * * * * * * * * * * //

TEST(Fourier, DerivativesMatchFiniteDifferences)
{
    auto m = makeMotion
    (
        "type fourier; joint 2; frequency 20; a0 0.1;"
        " a (1.2 0 0.05 0.01); b (0 0.3 -0.02 0.004);"
    );
    checkDerivatives(*m, 0, 1.0/20);
}


TEST(Fourier, MatchesDirectSum)
{
    const scalar f = 7, w = twoPi*f, a0 = -0.3;
    const std::vector<scalar> a{0.8, -0.1, 0.05, 0, 0.02, -0.01, 0.003};
    const std::vector<scalar> b{0.2, 0.15, 0, -0.04, 0.01, 0.002, -0.001};

    auto m = makeMotion
    (
        "type fourier; joint 0; frequency 7; a0 -0.3;"
        " a (0.8 -0.1 0.05 0 0.02 -0.01 0.003);"
        " b (0.2 0.15 0 -0.04 0.01 0.002 -0.001);"
    );

    for (label k = 0; k < 50; ++k)
    {
        const scalar t = 0.0123*k - 0.2;

        // Direct sum with one cos/sin call per harmonic
        scalar q = a0, qDot = 0, qDdot = 0;
        for (size_t n = 1; n <= a.size(); ++n)
        {
            const scalar nw = n*w;
            const scalar c = std::cos(nw*t), s = std::sin(nw*t);
            q += a[n-1]*c + b[n-1]*s;
            qDot += nw*(-a[n-1]*s + b[n-1]*c);
            qDdot -= nw*nw*(a[n-1]*c + b[n-1]*s);
        }

        const jointState st = eval(*m, 0, t);
        EXPECT_NEAR(st.q, q, 1e-12);
        EXPECT_NEAR(st.qDot, qDot, 1e-12*w);
        EXPECT_NEAR(st.qDdot, qDdot, 1e-11*w*w);
    }

    // t = 0: q = a0 + sum a_n
    scalar q0 = a0;
    for (const scalar an : a)
    {
        q0 += an;
    }
    EXPECT_NEAR(eval(*m, 0, 0).q, q0, 1e-14);
}


TEST(Fourier, OneCoefficientListDefaultsOtherToZeros)
{
    // Only b: q = b_1 sin(w t); only a: q = a0 + a_1 cos(w t) + a_2 cos(2 w t)
    auto mb = makeMotion("type fourier; joint 0; frequency 2; b (0.5);");
    auto ma = makeMotion
    (
        "type fourier; joint 0; frequency 2; a0 1; a (0.5 0.25);"
    );
    const scalar w = twoPi*2;

    for (const scalar t : {0.0, 0.03, 0.11, 0.4})
    {
        EXPECT_NEAR(eval(*mb, 0, t).q, 0.5*std::sin(w*t), 1e-14);
        EXPECT_NEAR
        (
            eval(*ma, 0, t).q,
            1 + 0.5*std::cos(w*t) + 0.25*std::cos(2*w*t),
            1e-14
        );
    }
}


TEST(Errors, FourierBadCoefficients)
{
    expectMotionError
    (
        "type fourier; joint 0; frequency 2; a0 1;", {"'a'", "'b'"}
    );
    expectMotionError
    (
        "type fourier; joint 0; frequency 2; a (1 2); b (1);",
        {"'a'", "'b'", "same length"}
    );
    expectMotionError
    (
        "type fourier; joint 0; frequency 2; a ();", {"'a'", "'b'", "empty"}
    );
}


// ************************************************************************* //
