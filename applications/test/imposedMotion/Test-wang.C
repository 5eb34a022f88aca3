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
    flapFoamTest-imposedMotion: imposedMotions::wang (flapping and pitching
    waveforms): derivatives against finite differences for K over its
    range, closed-form values, the small-K sinusoid and the large-K limits;
    K out of range and an unknown waveform are FatalIOErrors.

\*---------------------------------------------------------------------------*/

#include "imposedMotionTests.H"

// * * * * * * * * * * * * * * * * * wang  * * * * * * * * * * * * * * * * * //

TEST(Wang, FlappingDerivativesMatchFiniteDifferences)
{
    for (const char* K : {"0.01", "0.5", "0.9", "0.99"})
    {
        SCOPED_TRACE(std::string("flapping K = ") + K);
        auto m = makeMotion
        (
            std::string("type wang; joint 1; waveform flapping;"
            " amplitude 1.309; frequency 20; phase 0.2; offset 0.1; K ")
          + K + ";"
        );
        checkDerivatives(*m, 0, 1.0/20);
    }
}


TEST(Wang, PitchingDerivativesMatchFiniteDifferences)
{
    for (const char* K : {"0.01", "1", "5", "20"})
    {
        SCOPED_TRACE(std::string("pitching K = ") + K);
        auto m = makeMotion
        (
            std::string("type wang; joint 1; waveform pitching;"
            " amplitude 0.785; frequency 20; phase -0.4; offset 0.05; K ")
          + K + ";"
        );
        checkDerivatives(*m, 0, 1.0/20);
    }
}


TEST(Wang, ClosedFormValues)
{
    const scalar A = 1.309, f = 20, T = 1/f, w = twoPi*f, K = 0.7;

    // Flapping: q(0) = A (maximum, at rest), q(T/4) = 0 with
    // qDot = -A w K/asin(K), q(T/2) = -A
    auto flap = makeMotion
    (
        "type wang; joint 0; waveform flapping; amplitude 1.309;"
        " frequency 20; K 0.7;"
    );
    const jointState f0 = eval(*flap, 0, 0);
    EXPECT_NEAR(f0.q, A, 1e-14);
    EXPECT_NEAR(f0.qDot, 0, 1e-12);
    const jointState f1 = eval(*flap, 0, T/4);
    EXPECT_NEAR(f1.q, 0, 1e-14);
    EXPECT_NEAR(f1.qDot, -A*w*K/std::asin(K), 1e-12*A*w);
    EXPECT_NEAR(eval(*flap, 0, T/2).q, -A, 1e-14);

    // Pitching: q(0) = 0 with qDot = A w K/tanh(K), q(T/4) = A
    auto pitch = makeMotion
    (
        "type wang; joint 0; waveform pitching; amplitude 1.309;"
        " frequency 20; K 0.7; offset 0.2;"
    );
    const jointState p0 = eval(*pitch, 0, 0);
    EXPECT_NEAR(p0.q, 0.2, 1e-14);
    EXPECT_NEAR(p0.qDot, A*w*K/std::tanh(K), 1e-12*A*w);
    EXPECT_NEAR(p0.qDdot, 0, 1e-12*A*w*w);
    EXPECT_NEAR(eval(*pitch, 0, T/4).q, 0.2 + A, 1e-14);
    EXPECT_NEAR(eval(*pitch, 0, 3*T/4).q, 0.2 - A, 1e-14);
}


TEST(Wang, SmallKApproachesSinusoid)
{
    // asin(K c)/asin(K) = c (1 + O(K^2)), tanh(K s)/tanh(K) = s (1 + O(K^2))
    const scalar A = 1.2, f = 5, w = twoPi*f, phase = 0.3;

    auto flap = makeMotion
    (
        "type wang; joint 0; waveform flapping; amplitude 1.2; frequency 5;"
        " phase 0.3; K 1e-5;"
    );
    auto pitch = makeMotion
    (
        "type wang; joint 0; waveform pitching; amplitude 1.2; frequency 5;"
        " phase 0.3; K 1e-5;"
    );

    for (label k = 0; k < 20; ++k)
    {
        const scalar t = 0.0137*k;
        const scalar th = w*t + phase;

        const jointState sf = eval(*flap, 0, t);
        EXPECT_NEAR(sf.q, A*std::cos(th), 1e-9*A);
        EXPECT_NEAR(sf.qDot, -A*w*std::sin(th), 1e-9*A*w);
        EXPECT_NEAR(sf.qDdot, -A*w*w*std::cos(th), 1e-9*A*w*w);

        const jointState sp = eval(*pitch, 0, t);
        EXPECT_NEAR(sp.q, A*std::sin(th), 1e-9*A);
        EXPECT_NEAR(sp.qDot, A*w*std::cos(th), 1e-9*A*w);
        EXPECT_NEAR(sp.qDdot, -A*w*w*std::sin(th), 1e-9*A*w*w);
    }
}


TEST(Wang, LargeKLimits)
{
    // Flapping K -> 1: triangle wave, q(T/8) -> A/2
    auto flap = makeMotion
    (
        "type wang; joint 0; waveform flapping; amplitude 1; frequency 1;"
        " K 0.9999999999;"
    );
    EXPECT_NEAR(eval(*flap, 0, 0.125).q, 0.5, 1e-4);
    // ... with constant speed 4 A f away from the reversals
    EXPECT_NEAR(eval(*flap, 0, 0.125).qDot, -4, 1e-3);

    // Pitching K large: square wave, q(T/8) -> A
    auto pitch = makeMotion
    (
        "type wang; joint 0; waveform pitching; amplitude 1; frequency 1;"
        " K 50;"
    );
    EXPECT_NEAR(eval(*pitch, 0, 0.125).q, 1, 1e-12);
    EXPECT_NEAR(eval(*pitch, 0, 0.625).q, -1, 1e-12);
}


TEST(Errors, WangKOutOfRange)
{
    // Flapping: 0 < K < 1
    for (const char* K : {"1.2", "1", "0", "-0.5"})
    {
        expectMotionError
        (
            std::string("type wang; joint 0; waveform flapping; amplitude 1;"
            " frequency 2; K ") + K + ";",
            {"K " + std::string(K) + ":", "(0, 1)", "flapping"}
        );
    }

    // Pitching: K > 0
    for (const char* K : {"-1", "0"})
    {
        expectMotionError
        (
            std::string("type wang; joint 0; waveform pitching; amplitude 1;"
            " frequency 2; K ") + K + ";",
            {"K " + std::string(K) + ":", "> 0", "pitching"}
        );
    }

    // Valid at the limits' neighbourhood
    EXPECT_NO_THROW
    (
        makeMotion
        (
            "type wang; joint 0; waveform flapping; amplitude 1;"
            " frequency 2; K 0.99;"
        )
    );
    EXPECT_NO_THROW
    (
        makeMotion
        (
            "type wang; joint 0; waveform pitching; amplitude 1;"
            " frequency 2; K 1e-8;"
        )
    );
}


TEST(Errors, WangUnknownWaveform)
{
    expectMotionError
    (
        "type wang; joint 0; waveform heaving; amplitude 1; frequency 2;"
        " K 0.5;",
        {"waveform heaving unknown", "flapping", "pitching"}
    );
}


// ************************************************************************* //
