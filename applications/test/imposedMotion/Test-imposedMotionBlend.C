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
    flapFoamTest-imposedMotion: imposedMotionBlend and imposedMotionList::set,
    the run-time parameter changes of a controller: q, qDot, qDdot
    continuous at the start and end of a blend, exact derivatives inside
    (finite differences), the old motion before and the new one after
    exactly, a change during a running blend, a frequency change without
    phase jump, the chain bounded, the state written and read back bit for
    bit, bad input.

\*---------------------------------------------------------------------------*/

#include "imposedMotionTests.H"

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

const scalar f0 = 20;           // [Hz]
const scalar T0 = 1/f0;         // period [s]
const scalar Tb = 0.25*T0;      // blend time
const scalar t0 = 0.0113;       // first change
const std::string flapText =
    "type harmonic; joint 0; amplitude 1.0; frequency 20; phase 0.3;"
    " offset 0.1;";
const std::string pitchText =
    "type wang; joint 1; waveform pitching; amplitude 0.7; frequency 20;"
    " K 2;";


//- Model dictionary with the two entries flap (harmonic) and pitch (wang)
dictionary modelDict()
{
    return makeDict
    (
        "imposedMotion { flap {" + flapText + "} pitch {" + pitchText + "} }"
    );
}


//- The list of modelDict
imposedMotionList makeList()
{
    return imposedMotionList(modelDict(), labelList(2, 1));
}


//- The blend of one entry of text
imposedMotionBlend makeBlend(const std::string& text)
{
    return imposedMotionBlend(*makeMotion(text));
}


jointState eval(const imposedMotionBlend& b, const scalar t)
{
    jointState s{0, 0, 0};
    b.evaluate(0, t, s.q, s.qDot, s.qDdot);
    return s;
}


//- Largest |q|, |qDot|, |qDdot| of a harmonic of amplitude A, frequency f
jointState harmonicScale(const scalar A, const scalar f)
{
    const scalar w = twoPi*f;
    return jointState{A, A*w, A*w*w};
}


//- Expect a and b equal within tol times scale, component by component
void expectClose
(
    const jointState& a,
    const jointState& b,
    const jointState& scale,
    const scalar tol
)
{
    EXPECT_LE(mag(a.q - b.q), tol*scale.q) << a.q << " vs " << b.q;
    EXPECT_LE(mag(a.qDot - b.qDot), tol*scale.qDot)
        << a.qDot << " vs " << b.qDot;
    EXPECT_LE(mag(a.qDdot - b.qDdot), tol*scale.qDdot)
        << a.qDdot << " vs " << b.qDdot;
}


void expectEqual(const jointState& a, const jointState& b)
{
    EXPECT_EQ(a.q, b.q);
    EXPECT_EQ(a.qDot, b.qDot);
    EXPECT_EQ(a.qDdot, b.qDdot);
}


//- Continuity at time tc: the states at tc -+ h (h = 1e-12 Tb) equal
//- within 1e-10 of the scale (a linear blend: 0.15 in qDot)
void expectContinuous
(
    const imposedMotionBlend& b,
    const scalar tc,
    const jointState& scale
)
{
    SCOPED_TRACE("continuity at t = " + std::to_string(tc));
    const scalar h = 1e-12*Tb;
    expectClose(eval(b, tc - h), eval(b, tc + h), scale, 1e-10);
}


//- qDot and qDdot against central differences of q and qDot at 101
//- times inside (ta, tb), relative to the scale: 1e-7.  Not at the ends
//- of a blend: the jerk (s''') jumps there, O(h) in the difference.
void expectDerivatives
(
    const imposedMotionBlend& b,
    const scalar ta,
    const scalar tb,
    const jointState& scale
)
{
    const scalar h = 1e-7*T0;
    for (label k = 0; k <= 100; ++k)
    {
        const scalar t = ta + (tb - ta)*(k + 0.37)/101.0;
        const jointState s = eval(b, t);
        const jointState sp = eval(b, t + h);
        const jointState sm = eval(b, t - h);

        EXPECT_LE(mag((sp.q - sm.q)/(2*h) - s.qDot), 1e-7*scale.qDot)
            << "t = " << t;
        EXPECT_LE(mag((sp.qDot - sm.qDot)/(2*h) - s.qDdot), 1e-7*scale.qDdot)
            << "t = " << t;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Blends  * * * * * * * * * * * * * * * * //

TEST(Blend, OldBeforeAndNewAfterExactly)
{
    imposedMotionBlend b(makeBlend(flapText));
    b.set("amplitude", 1.3, t0, Tb);
    ASSERT_EQ(b.nStages(), 2);

    auto oldMotion = makeMotion(flapText);
    auto newMotion = makeMotion
    (
        "type harmonic; joint 0; amplitude 1.3; frequency 20; phase 0.3;"
        " offset 0.1;"
    );

    for (const scalar t : {-0.3, 0.0, 0.5*t0, t0})
    {
        expectEqual(eval(b, t), eval(*oldMotion, 0, t));
    }
    for (const scalar t : {t0 + Tb, t0 + 1.5*Tb, 3.7})
    {
        expectEqual(eval(b, t), eval(*newMotion, 0, t));
    }

    EXPECT_FALSE(b.blending(t0));
    EXPECT_TRUE(b.blending(t0 + 0.5*Tb));
    EXPECT_FALSE(b.blending(t0 + Tb));
    EXPECT_EQ(b.get("amplitude"), 1.3);
    EXPECT_EQ(b.get("offset"), 0.1);

    // Any value is kept to the bit (not formatted at the stream precision)
    b.set("amplitude", 1.0/3, t0 + Tb, Tb);
    EXPECT_EQ(b.get("amplitude"), 1.0/3);
}


TEST(Blend, ContinuousAtStartAndEndExactDerivativesInside)
{
    for (const char* key : {"amplitude", "offset", "phase", "frequency"})
    {
        SCOPED_TRACE(key);
        imposedMotionBlend b(makeBlend(flapText));
        const scalar value = std::string(key) == "frequency" ? 24 : 0.4;
        b.set(key, value, t0, Tb);

        const jointState scale = harmonicScale(1.0, 24);
        expectContinuous(b, t0, scale);
        expectContinuous(b, t0 + Tb, scale);
        expectDerivatives(b, t0, t0 + Tb, scale);

        // The blend is not trivial: inside, q differs from both motions
        const jointState mid = eval(b, t0 + 0.5*Tb);
        EXPECT_GT(mag(mid.q - eval(*makeMotion(flapText), 0, t0 + 0.5*Tb).q),
            1e-3);
    }

    // wang: the shape K
    imposedMotionBlend w(makeBlend(pitchText));
    w.set("K", 0.5, t0, Tb);
    const jointState scale = harmonicScale(0.7*3, 20);
    expectContinuous(w, t0, scale);
    expectContinuous(w, t0 + Tb, scale);
    expectDerivatives(w, t0, t0 + Tb, scale);
}


TEST(Blend, ChangeDuringRunningBlend)
{
    imposedMotionBlend b(makeBlend(flapText));
    const scalar t1 = t0 + 0.4*Tb, Tb1 = 0.5*Tb;
    b.set("amplitude", 1.3, t0, Tb);
    b.set("frequency", 25, t1, Tb1);
    EXPECT_EQ(b.nStages(), 3);
    EXPECT_EQ(b.get("frequency"), 25);
    EXPECT_EQ(b.get("amplitude"), 1.3);

    const jointState scale = harmonicScale(1.3, 25);
    for (const scalar tc : {t0, t1, t1 + Tb1, t0 + Tb})
    {
        expectContinuous(b, tc, scale);
    }
    expectDerivatives(b, t0 - 0.1*Tb, t0 + 1.5*Tb, scale);

    // After both: amplitude 1.3, frequency 25, phase continuous at t1
    const scalar phase = 0.3 + twoPi*(20 - 25)*t1;
    const scalar w = twoPi*25;
    for (const scalar t : {t0 + Tb, t0 + 2*Tb, 0.9})
    {
        const jointState s = eval(b, t);
        EXPECT_NEAR(s.q, 0.1 + 1.3*std::cos(w*t + phase), 1e-12);
        EXPECT_NEAR(s.qDot, -1.3*w*std::sin(w*t + phase), 1e-12*scale.qDot);
    }
}


TEST(Blend, SeveralParametersAtOneUpdate)
{
    // A controller sets amplitude, frequency and offset at the same t0
    imposedMotionBlend b(makeBlend(flapText));
    b.set("amplitude", 1.3, t0, Tb);
    b.set("frequency", 25, t0, Tb);
    b.set("offset", -0.2, t0, Tb);
    EXPECT_EQ(b.nStages(), 4);

    const jointState scale = harmonicScale(1.3, 25);
    expectContinuous(b, t0, scale);
    expectContinuous(b, t0 + Tb, scale);
    expectDerivatives(b, t0, t0 + Tb, scale);

    const scalar phase = 0.3 + twoPi*(20 - 25)*t0;
    for (const scalar t : {t0 + Tb, 0.7})
    {
        EXPECT_NEAR(eval(b, t).q, -0.2 + 1.3*std::cos(twoPi*25*t + phase),
            1e-12);
    }

    // The next update, after the blends: one stage plus the new one
    b.set("amplitude", 1.1, t0 + 2*Tb, Tb);
    EXPECT_EQ(b.nStages(), 2);
}


TEST(Blend, FrequencyChangeWithoutPhaseJump)
{
    // Abrupt (Tb = 0): q stays continuous, only the phase rate changes
    imposedMotionBlend b(makeBlend(flapText));
    b.set("frequency", 31, t0, 0);

    const scalar h = 1e-15;
    const jointState before = eval(b, t0 - h);
    const jointState after = eval(b, t0 + h);
    EXPECT_NEAR(after.q, before.q, 1e-12);
    EXPECT_NEAR(after.qDot, before.qDot*31/20, 1e-10*twoPi*31);

    // The new motion: q = 0.1 + std::cos(2 pi 31 t + phase'), same phase at t0
    const scalar phase = 0.3 + twoPi*(20 - 31)*t0;
    for (const scalar t : {t0, t0 + 0.01, 0.5})
    {
        EXPECT_NEAR(eval(b, t + h).q, 0.1 + std::cos(twoPi*31*(t + h) + phase),
            1e-12);
    }

    // A second change, on the shifted clock: continuous again
    b.set("frequency", 17, t0 + 0.01, 0);
    EXPECT_NEAR
    (
        eval(b, t0 + 0.01 - h).q, eval(b, t0 + 0.01 + h).q, 1e-12
    );
}


TEST(Blend, ChainStaysBounded)
{
    // A change every 0.3 Tb: at most 1 + 4 blends run at a change
    imposedMotionBlend b(makeBlend(flapText));
    const scalar dt = 0.3*Tb;
    label most = 0;
    for (label k = 0; k < 50; ++k)
    {
        const scalar t = t0 + k*dt;
        b.set("amplitude", 1 + 0.1*(k % 3), t, Tb);
        most = max(most, b.nStages());
        expectContinuous(b, t, harmonicScale(1.2, 20));
    }
    EXPECT_LE(most, 6);
    expectDerivatives(b, t0 + 45*dt, t0 + 52*dt, harmonicScale(1.2, 20));

    // Once the last blend has ended, one change leaves two stages
    b.set("amplitude", 1, t0 + 49*dt + Tb, Tb);
    EXPECT_EQ(b.nStages(), 2);
}


// * * * * * * * * * * * * * * * * * List  * * * * * * * * * * * * * * * * //

TEST(BlendList, SetEvaluatesAndWritesTheStateBitForBit)
{
    imposedMotionList run(makeList());
    run.set("flap", "amplitude", 1.3, t0, Tb);
    run.set("flap", "frequency", 25, t0 + 0.4*Tb, Tb);
    run.set("pitch", "amplitude", 0.5, t0 + 0.1*Tb, Tb);
    EXPECT_EQ(run.get("flap", "frequency"), 25);
    EXPECT_EQ(run.blend("pitch").current().dict().get<scalar>("amplitude"),
        0.5);

    run.set("pitch", "offset", 1.0/7, t0 + 0.2*Tb, Tb);

    // The state at a restart in the middle of the blends, through text
    // at 17 digits (as eABAMotion::writeState), the stream precision 6
    dictionary state;
    ASSERT_EQ(IOstream::defaultPrecision(), 6u);
    run.writeState(state);
    OStringStream os;
    os.precision(17);
    os << state;
    const dictionary readBack(IStringStream(os.str())());

    imposedMotionList restarted(makeList());
    restarted.readState(readBack);

    const auto compare = [&]()
    {
        scalarField q1(2), qDot1(2), qDdot1(2), q2(2), qDot2(2), qDdot2(2);
        for (label k = 0; k < 200; ++k)
        {
            const scalar t = t0 + 0.45*Tb + k*0.013*Tb;
            run.evaluate(t, q1, qDot1, qDdot1);
            restarted.evaluate(t, q2, qDot2, qDdot2);
            for (label j = 0; j < 2; ++j)
            {
                ASSERT_EQ(q1[j], q2[j]) << "t = " << t;
                ASSERT_EQ(qDot1[j], qDot2[j]) << "t = " << t;
                ASSERT_EQ(qDdot1[j], qDdot2[j]) << "t = " << t;
            }
        }
    };
    compare();

    // Both continue with the same change
    run.set("flap", "phase", 0.1, t0 + 0.6*Tb, Tb);
    restarted.set("flap", "phase", 0.1, t0 + 0.6*Tb, Tb);
    compare();

    // A state without imposedMotionState (a fresh start): as read
    imposedMotionList fresh(makeList());
    fresh.readState(dictionary());
    EXPECT_EQ(fresh.blend("flap").nStages(), 1);
}


// * * * * * * * * * * * * * * * * Bad input * * * * * * * * * * * * * * * //

TEST(BlendErrors, UnknownEntryOrParameter)
{
    imposedMotionList list(makeList());

    expectError
    (
        [&](){ list.set("wing", "amplitude", 1, t0, Tb); },
        {"'wing'", "flap", "pitch"}
    );
    expectError
    (
        [&](){ list.set("flap", "amplitud", 1, t0, Tb); },
        {"'amplitud'", "'flap'", "harmonic", "amplitude", "offset",
         "frequency", "phase"}
    );
    expectError
    (
        [&](){ list.get("pitch", "waveform"); },
        {"'waveform'", "'pitch'", "K"}
    );

    // wangParametrization: not the frequencies; tabulated: the offset
    imposedMotionBlend wp(makeBlend(wangParametrizationText("")));
    expectError
    (
        [&](){ wp.set("fphi", 25, t0, Tb); },
        {"'fphi'", "Aphi", "Aalpha", "Kphi", "Kalpha"}
    );
}


TEST(BlendErrors, BlendTimeAndOrder)
{
    imposedMotionList list(makeList());

    expectError
    (
        [&](){ list.set("flap", "amplitude", 1, t0, -1e-3); },
        {"-0.001", "'amplitude'", "'flap'", ">= 0"}
    );

    list.set("flap", "amplitude", 1.2, t0, Tb);
    expectError
    (
        [&](){ list.set("flap", "offset", 0, 0.5*t0, Tb); },
        {"'offset'", "'flap'", "time order"}
    );
}


TEST(BlendErrors, ValueCheckedAsInTheDictionary)
{
    imposedMotionList list(makeList());
    expectIOError
    (
        [&](){ list.set("flap", "frequency", -2, t0, Tb); },
        {"frequency -2:", "a value > 0 is allowed"}
    );
    expectIOError
    (
        [&](){ list.set("pitch", "K", 0, t0, Tb); },
        {"K 0:", "> 0 (the pitching waveform)"}
    );
}


TEST(BlendErrors, StateOfAnotherModel)
{
    imposedMotionList list(makeList());

    // An entry missing from the state
    dictionary state;
    list.writeState(state);
    state.subDict("imposedMotionState").remove("pitch");
    expectIOError([&](){ list.readState(state); }, {"pitch"});

    // A stage of another type
    dictionary other;
    list.writeState(other);
    dictionary& stage0 =
        other.subDict("imposedMotionState").subDict("flap").subDict("stage0");
    stage0.set("parameters", makeDict(pitchText));
    expectIOError
    (
        [&](){ list.readState(other); },
        {"'flap'", "wang", "harmonic", "another model"}
    );
}


// ************************************************************************* //
