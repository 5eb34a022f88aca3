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
    flapFoamTest-imposedMotion: imposedMotions::wangParametrization (the
    authors' two-joint Wang motion): derivatives, joints and the standard
    start equal to two wang motions, the mid-stroke start; bad input is a
    FatalIOError naming the key.

\*---------------------------------------------------------------------------*/

#include "imposedMotionTests.H"

// * * * * * * * * * * * * * * wangParametrization * * * * * * * * * * * * * //

TEST(WangParametrization, DerivativesMatchFiniteDifferences)
{
    for
    (
        const char* type
      : {"", "motionType standard;", "motionType midStart;"}
    )
    {
        SCOPED_TRACE(type);
        auto m = makeMotion(wangParametrizationText(type));
        checkDerivatives(*m, 0, 1.0/20);
        checkDerivatives(*m, 1, 1.0/20);
    }

    // The authors' dictionary (K = 0.01 for both)
    auto m = makeMotion
    (
        "type wangParametrization; jointList (3 4); Aphi 1.309; fphi 20;"
        " Kphi 0.01; Aalpha 0.785; falpha 20; Kalpha 0.01;"
        " motionType midStart;"
    );
    checkDerivatives(*m, 0, 1.0/20);
    checkDerivatives(*m, 1, 1.0/20);
}


TEST(WangParametrization, JointsAndStandardMatchesWang)
{
    auto m = makeMotion(wangParametrizationText(""));

    ASSERT_EQ(m->joints().size(), 2);
    EXPECT_EQ(m->joints()[0], 3);
    EXPECT_EQ(m->joints()[1], 4);
    EXPECT_EQ(m->jointsKey(), "jointList");

    auto flap = makeMotion
    (
        "type wang; joint 3; waveform flapping; amplitude 1.309;"
        " frequency 20; K 0.3;"
    );
    auto pitch = makeMotion
    (
        "type wang; joint 4; waveform pitching; amplitude 0.785;"
        " frequency 20; K 2;"
    );

    for (label k = 0; k < 30; ++k)
    {
        const scalar t = 0.00317*k - 0.01;
        const jointState a = eval(*m, 0, t), b = eval(*flap, 0, t);
        const jointState c = eval(*m, 1, t), d = eval(*pitch, 0, t);
        EXPECT_DOUBLE_EQ(a.q, b.q);
        EXPECT_DOUBLE_EQ(a.qDot, b.qDot);
        EXPECT_DOUBLE_EQ(a.qDdot, b.qDdot);
        EXPECT_DOUBLE_EQ(c.q, d.q);
        EXPECT_DOUBLE_EQ(c.qDot, d.qDot);
        EXPECT_DOUBLE_EQ(c.qDdot, d.qDdot);
    }

    // Standard: phi(0) = Aphi, alpha(0) = 0
    EXPECT_NEAR(eval(*m, 0, 0).q, 1.309, 1e-14);
    EXPECT_NEAR(eval(*m, 1, 0).q, 0, 1e-14);
}


TEST(WangParametrization, MidStart)
{
    const scalar T = 1.0/20;
    auto stdm = makeMotion(wangParametrizationText(""));
    auto mid = makeMotion(wangParametrizationText("motionType midStart;"));

    // Mid-stroke start: phi(0) = 0 moving towards +Aphi, alpha(0) = Aalpha
    const jointState phi0 = eval(*mid, 0, 0);
    EXPECT_NEAR(phi0.q, 0, 1e-14);
    EXPECT_GT(phi0.qDot, 0);
    EXPECT_NEAR(eval(*mid, 0, T/4).q, 1.309, 1e-14);
    EXPECT_NEAR(eval(*mid, 1, 0).q, 0.785, 1e-14);
    EXPECT_NEAR(eval(*mid, 1, T/4).q, 0, 1e-14);

    // phi_mid(t) = phi_std(t - T/4), alpha_mid(t) = -alpha_std(t - T/4)
    for (label k = 0; k < 40; ++k)
    {
        const scalar t = 0.00291*k - 0.02;
        const jointState pm = eval(*mid, 0, t), ps = eval(*stdm, 0, t - T/4);
        const jointState am = eval(*mid, 1, t), as = eval(*stdm, 1, t - T/4);

        EXPECT_NEAR(pm.q, ps.q, 1e-12);
        EXPECT_NEAR(pm.qDot, ps.qDot, 1e-9*mag(ps.qDot) + 1e-9);
        EXPECT_NEAR(pm.qDdot, ps.qDdot, 1e-9*mag(ps.qDdot) + 1e-6);
        EXPECT_NEAR(am.q, -as.q, 1e-12);
        EXPECT_NEAR(am.qDot, -as.qDot, 1e-9*mag(as.qDot) + 1e-9);
        EXPECT_NEAR(am.qDdot, -as.qDdot, 1e-9*mag(as.qDdot) + 1e-6);
    }
}


TEST(Errors, WangParametrizationBadInput)
{
    // jointList with other than 2 entries
    for (const char* list : {"(3)", "(3 4 5)", "()"})
    {
        expectMotionError
        (
            "type wangParametrization; Aphi 1; fphi 20; Kphi 0.5; Aalpha 1;"
            " falpha 20; Kalpha 1; jointList " + std::string(list) + ";",
            {"'jointList'", "exactly 2"}
        );
    }

    // K ranges name their own keys
    expectMotionError
    (
        "type wangParametrization; jointList (0 1); Aphi 1; fphi 20;"
        " Kphi 1.5; Aalpha 1; falpha 20; Kalpha 1;",
        {"'Kphi'", "0 < Kphi < 1"}
    );
    expectMotionError
    (
        "type wangParametrization; jointList (0 1); Aphi 1; fphi 20;"
        " Kphi 0.5; Aalpha 1; falpha 20; Kalpha -1;",
        {"'Kalpha'", "Kalpha > 0"}
    );

    // Unknown motionType lists the allowed ones
    expectMotionError
    (
        wangParametrizationText("motionType midStartControl_z_PD;"),
        {"'motionType'", "midStartControl_z_PD", "standard", "midStart"}
    );
}


// ************************************************************************* //
