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
    start equal to two wang motions, the mid-stroke start equal to the
    authors' code (their formulas, their dictionary's numbers), their
    two-wing type; bad input is a FatalIOError naming the key.

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

    // The authors' mid-stroke start: phi(0) = 0 moving towards -Aphi,
    // alpha(0) = 0, alpha(T/4) = Aalpha, alpha(T/2) = 2 Aalpha
    const jointState phi0 = eval(*mid, 0, 0);
    EXPECT_NEAR(phi0.q, 0, 1e-14);
    EXPECT_LT(phi0.qDot, 0);
    EXPECT_NEAR(eval(*mid, 0, T/4).q, -1.309, 1e-14);
    EXPECT_NEAR(eval(*mid, 1, 0).q, 0, 1e-14);
    EXPECT_NEAR(eval(*mid, 1, T/4).q, 0.785, 1e-14);
    EXPECT_NEAR(eval(*mid, 1, T/2).q, 2*0.785, 1e-14);

    // phi_mid(t) = -phi_std(t - T/4), alpha_mid(t) = alpha_std(t - T/4) + A
    for (label k = 0; k < 40; ++k)
    {
        const scalar t = 0.00291*k - 0.02;
        const jointState pm = eval(*mid, 0, t), ps = eval(*stdm, 0, t - T/4);
        const jointState am = eval(*mid, 1, t), as = eval(*stdm, 1, t - T/4);

        EXPECT_NEAR(pm.q, -ps.q, 1e-12);
        EXPECT_NEAR(pm.qDot, -ps.qDot, 1e-9*mag(ps.qDot) + 1e-9);
        EXPECT_NEAR(pm.qDdot, -ps.qDdot, 1e-9*mag(ps.qDdot) + 1e-6);
        EXPECT_NEAR(am.q, as.q + 0.785, 1e-12);
        EXPECT_NEAR(am.qDot, as.qDot, 1e-9*mag(as.qDot) + 1e-9);
        EXPECT_NEAR(am.qDdot, as.qDdot, 1e-9*mag(as.qDdot) + 1e-6);
    }
}


TEST(WangParametrization, MidStartIsTheAuthorsMotion)
{
    // The entry of the authors' TEST_CASE/All/constant/dynamicMeshDict
    // (github polettiRomain/eABA), their keys body and initialConditions
    // included (ignored, with a warning)
    const scalar Aphi = -1.30899694, Kphi = 0.01, Aalpha = 0.78;
    const scalar Kalpha = 0.01, f = 20;
    auto m = makeMotion
    (
        "type wangParametrization; jointList (3 4); motionType \"midStart\";"
        " body Wing; Aphi -1.30899694; fphi 20; Kphi 0.01; Aalpha 0.78;"
        " falpha 20; Kalpha 0.01; initialConditions (0 0);"
    );

    // Their q (wangParametrization.C, loadImposedMotion, midStart), their
    // qDot and qDdot of phi and their qDdot of alpha; the exact qDot of
    // their alpha (theirs has cosh(K sin) where it needs cosh(K cos))
    for (label k = 0; k < 50; ++k)
    {
        const scalar t = 0.00173*k - 0.01;
        const scalar w = twoPi*f;
        const scalar s = std::sin(w*t), c = std::cos(w*t);

        const scalar phi = -Aphi/std::asin(Kphi)*std::asin(Kphi*s);
        const scalar phiDot =
            -Aphi/std::asin(Kphi)*w*Kphi*c/std::sqrt(1 - sqr(Kphi*s));
        const scalar phiDdot =
            -(Aphi*Kphi*w*w*s*(sqr(Kphi*s) + sqr(Kphi*c) - 1))
           /(std::asin(Kphi)*std::pow(1 - sqr(Kphi*s), 1.5));

        const scalar S = Aalpha/std::tanh(Kalpha);
        const scalar alpha = -S*std::tanh(Kalpha*c) + Aalpha;
        const scalar sech2 = 1/sqr(std::cosh(Kalpha*c));
        const scalar alphaDot = S*Kalpha*w*s*sech2;
        const scalar alphaDdot =
            S*Kalpha*w*w*sech2*(c + 2*Kalpha*s*s*std::tanh(Kalpha*c));

        const jointState p = eval(*m, 0, t), a = eval(*m, 1, t);
        EXPECT_NEAR(p.q, phi, 1e-14);
        EXPECT_NEAR(p.qDot, phiDot, 1e-12*mag(phiDot) + 1e-12);
        EXPECT_NEAR(p.qDdot, phiDdot, 1e-12*mag(phiDdot) + 1e-9);
        EXPECT_NEAR(a.q, alpha, 1e-14);
        EXPECT_NEAR(a.qDot, alphaDot, 1e-12*mag(alphaDot) + 1e-12);
        EXPECT_NEAR(a.qDdot, alphaDdot, 1e-12*mag(alphaDdot) + 1e-9);
    }

    // Their qDot of alpha (cosh(K sin)) is the exact one to O(K^2): within
    // 2 K^2 = 2e-4 of the largest |qDot| at K = 0.01 (measured 1.00003e-4)
    scalar maxDiff = 0, maxQDot = 0;
    for (label k = 0; k < 200; ++k)
    {
        const scalar t = k/(200*f);
        const scalar w = twoPi*f;
        const scalar theirs =
            Aalpha/std::tanh(Kalpha)*Kalpha*w*std::sin(w*t)
           /sqr(std::cosh(Kalpha*std::sin(w*t)));
        maxDiff = max(maxDiff, mag(eval(*m, 1, t).qDot - theirs));
        maxQDot = max(maxQDot, mag(theirs));
    }
    EXPECT_GT(maxDiff, 0);
    EXPECT_LT(maxDiff, 2*sqr(Kalpha)*maxQDot);

    // The numbers at t = 0.0025 s: q3 = +0.4045, q4 = 0.0382
    EXPECT_NEAR(eval(*m, 0, 0.0025).q, 0.4045, 5e-5);
    EXPECT_NEAR(eval(*m, 1, 0.0025).q, 0.0382, 5e-5);

    // Exact derivatives, 1e-7 relative to the largest
    checkDerivatives(*m, 0, 1.0/f, 1e-7);
    checkDerivatives(*m, 1, 1.0/f, 1e-7);

    // write() gives back the dictionary's amplitudes
    const std::string text(writtenText(*m));
    EXPECT_EQ(makeDict(text).get<scalar>("Aphi"), Aphi) << text;
    EXPECT_EQ(makeDict(text).get<scalar>("Aalpha"), Aalpha) << text;
    auto again = makeMotion(text);
    EXPECT_EQ(eval(*again, 0, 0.0031).q, eval(*m, 0, 0.0031).q);
    EXPECT_EQ(eval(*again, 1, 0.0031).q, eval(*m, 1, 0.0031).q);
}


TEST(WangParametrization, MidStartTwoWings)
{
    auto one = makeMotion(wangParametrizationText("motionType midStart;"));
    auto two = makeMotion
    (
        "type wangParametrization; jointList (3 4 7 8); Aphi 1.309; fphi 20;"
        " Kphi 0.3; Aalpha 0.785; falpha 20; Kalpha 2;"
        " motionType midStart_2wings;"
    );

    EXPECT_EQ(two->joints(), labelList({3, 4, 7, 8}));

    // The authors' second wing: -phi, alpha
    for (label k = 0; k < 20; ++k)
    {
        const scalar t = 0.00291*k - 0.02;
        const jointState p = eval(*one, 0, t), a = eval(*one, 1, t);
        for (const label i : {0, 2})
        {
            const scalar sign = i == 0 ? 1 : -1;
            const jointState s = eval(*two, i, t);
            EXPECT_EQ(s.q, sign*p.q);
            EXPECT_EQ(s.qDot, sign*p.qDot);
            EXPECT_EQ(s.qDdot, sign*p.qDdot);
        }
        for (const label i : {1, 3})
        {
            const jointState s = eval(*two, i, t);
            EXPECT_EQ(s.q, a.q);
            EXPECT_EQ(s.qDot, a.qDot);
            EXPECT_EQ(s.qDdot, a.qDdot);
        }
    }

    for (label i = 0; i < 4; ++i)
    {
        checkDerivatives(*two, i, 1.0/20, 1e-7);
    }
}


TEST(Errors, WangParametrizationBadInput)
{
    // jointList with other than 2 entries (4 for midStart_2wings)
    for (const char* list : {"(3)", "(3 4 5)", "()"})
    {
        expectMotionError
        (
            "type wangParametrization; Aphi 1; fphi 20; Kphi 0.5; Aalpha 1;"
            " falpha 20; Kalpha 1; jointList " + std::string(list) + ";",
            {"'jointList'", "exactly 2"}
        );
    }
    expectMotionError
    (
        wangParametrizationText("motionType midStart_2wings;"),
        {"'jointList'", "midStart_2wings", "exactly 4"}
    );

    // K ranges name their own keys
    expectMotionError
    (
        "type wangParametrization; jointList (0 1); Aphi 1; fphi 20;"
        " Kphi 1.5; Aalpha 1; falpha 20; Kalpha 1;",
        {"Kphi 1.5:", "(0, 1) (the flapping waveform)"}
    );
    expectMotionError
    (
        "type wangParametrization; jointList (0 1); Aphi 1; fphi 20;"
        " Kphi 0.5; Aalpha 1; falpha 20; Kalpha -1;",
        {"Kalpha -1:", "> 0 (the pitching waveform)"}
    );

    // Unknown motionType lists the allowed ones; the authors' controllers
    // are named as such, the xzth ones with their converter
    expectMotionError
    (
        wangParametrizationText("motionType midStartControl_z_PD;"),
        {
            "motionType midStartControl_z_PD", "flight controller",
            "not a motion type of flapFoam", "docs/control.md",
            "standard", "midStart", "midStart_2wings"
        }
    );
    expectMotionError
    (
        wangParametrizationText("motionType midStartControl_xzth_linearPD;"),
        {
            "motionType midStartControl_xzth_linearPD",
            "flight controller", "flapfoam authors_control"
        }
    );
    expectMotionError
    (
        wangParametrizationText("motionType midstart;"),
        {"motionType midstart unknown: must be one of", "midStart"}
    );

    // A misspelled optional key lists the allowed keys
    expectMotionError
    (
        wangParametrizationText("motiontype midStart;"),
        {
            "'motiontype'", "allowed keys", "motionType", "Aphi", "Kalpha",
            "jointList", "authors' keys, ignored: body initialConditions"
        }
    );
}


// ************************************************************************* //
