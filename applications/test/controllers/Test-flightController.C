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
    flapFoamTest-controllers: the flight controller (libflapFoam
    Controllers, type PID) inside eABAMotion, on the model restart with a
    controller of two loops (the shoulder's amplitude from the fuselage's
    height, tanh; its offset from link2's pitch, linear), updated at 50 Hz
    and blended over half a period:
    - an update keeps the prescribed joint's q, qDot, qDdot continuous
      (1e-9) and, inside the blend, its torque equals inverse dynamics of
      the dense oracle (1e-10);
    - a restart in the middle of a blend and of a period continues as the
      uninterrupted run: states to 1e-12 over 60 steps (3 more updates),
      the control variables (integrals included) identical;
    - derivative mean: the mean rate since the last update;
    - the measures (position, velocity, orientation, angular velocity of a
      named body) against the joint state; the saturations; no integral
      wind-up while a linear output is clipped;
    - bad controller entries: FatalIOError naming the key and the value.

\*---------------------------------------------------------------------------*/

#include "rigidBodyTests.H"
#include "denseOracle.H"
#include "expectError.H"
#include "flightController.H"
#include "controlLoop.H"

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

const std::string controllerText
(
    "type PID; update rate; rate 50; blend 0.5; log off;"
    "loops {"
    " lift { entry shoulder; parameter amplitude; saturation tanh;"
    "  min 0.5; max 1.5;"
    "  terms { z { body fuselage; quantity position; component z;"
    "   setPoint table ((0 0) (1 0.1)); Kp -20; Ki -50; Kd -2; } } }"
    " trim { entry shoulder; parameter offset; saturation linear;"
    "  min -1.2; max -0.8; bias -0.9948;"
    "  terms { pitch { body link2; quantity orientation; component y;"
    "   setPoint 0.05; Kp 0.5; Ki 2; Kd 0.01; derivative mean; } } }"
    "}"
);


//- The model restart with the controller (text: its dictionary)
dictionary controlledModel(const std::string& text = controllerText)
{
    dictionary dict(readTestModel("restart"));
    dict.add("controller", dictFromString(text));
    return dict;
}


const scalar dt = 1e-3;

//- One step as the drivers take it
void advance(RBD::eABAMotion& m, const label step)
{
    const scalarField tau(m.nDoF(), Zero);
    const Field<spatialVector> fx(m.nBodies(), Zero);
    m.newTime();
    for (label iter = 0; iter < m.nIter(); ++iter)
    {
        m.solve(step*dt, dt, tau, fx);
    }
}


//- The measure of a term (Kp 1, set-point 0) for the model's kinematics
scalar measure(const RBD::rigidBodyModel& model, const std::string& text)
{
    controlTerm term(model, dictFromString(text + " setPoint 0; Kp 1;"));
    return term.update(0, 0, true);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(flightController, UpdateIsContinuousAndTorqueExact)
{
    testMotion motion(runTime(), controlledModel());
    for (label step = 1; step <= 21; ++step)
    {
        advance(motion, step);
    }
    ASSERT_TRUE(motion.controller());
    ASSERT_EQ(motion.controller()->nUpdates(), 1);

    const imposedMotionList& motions = motion.imposedMotions();
    EXPECT_NE(motions.get("shoulder", "amplitude"), 0.9948);
    EXPECT_NE(motions.get("shoulder", "offset"), -0.9948);

    // The update at t0 = 0.02: q, qDot, qDdot continuous (qDdot's change
    // across is O(h): 60 h/Tb^3 (q_new - q_old) from the blend's s'')
    const scalar t0 = 0.02, h = 1e-15;
    scalarField q[2], qDot[2], qDdot[2];
    for (label side = 0; side < 2; ++side)
    {
        q[side] = motion.state().q();
        qDot[side] = motion.state().qDot();
        qDdot[side] = motion.state().qDdot();
        motions.evaluate
        (
            t0 + (side ? h : -h), q[side], qDot[side], qDdot[side]
        );
    }
    EXPECT_LE(mag(q[1][1] - q[0][1]), 1e-9);
    EXPECT_LE(mag(qDot[1][1] - qDot[0][1]), 1e-9);
    EXPECT_LE(mag(qDdot[1][1] - qDdot[0][1]), 1e-9*mag(qDdot[0][1]) + 1e-9);

    // Inside the blend (0.02 to 0.03): the torque is inverse dynamics
    const denseOracle oracle(motion);
    const scalarField tau(motion.nDoF(), Zero);
    const Field<spatialVector> fx(motion.nBodies(), Zero);
    RBD::rigidBodyModelState state(motion.state());
    for (label k = 0; k < 10; ++k)
    {
        state.t() = t0 + 0.01*(k + 0.5)/10;
        motions.evaluate(state.t(), state.q(), state.qDot(), state.qDdot());
        motion.RBD::eABAModel::forwardDynamics(state, tau, fx);
        const VecX tauID
        (
            oracle.inverseDynamics
            (
                state.q(), state.qDot(), toEigen(state.qDdot()), true, fx
            )
        );
        EXPECT_LE
        (
            relErr
            (
                toEigen(motion.prescribedTau()),
                select(tauID, motion.prescribed())
            ),
            1e-10
        ) << "t = " << state.t();
    }
}


TEST(flightController, RestartInTheMiddleOfACycle)
{
    const unsigned oldPrecision = IOstream::defaultPrecision(17);

    RBD::eABAMotion motion(runTime(), controlledModel());
    for (label step = 1; step <= 25; ++step)
    {
        advance(motion, step);
    }
    ASSERT_EQ(motion.controller()->nUpdates(), 1);
    ASSERT_TRUE(motion.imposedMotions().blend("shoulder").blending(25*dt));

    // The model as written, the state as eABAMotion::writeState writes it
    OStringStream os;
    motion.write(os);
    const dictionary modelDict(dictFromString(os.str()));
    ASSERT_TRUE(modelDict.found("controller"));

    dictionary stateDict;
    motion.state().write(stateDict);
    motion.imposedMotions().writeState(stateDict);
    motion.controller()->writeState(stateDict);
    {
        // Through text, as the file is written and read
        OStringStream ss;
        stateDict.write(ss, false);
        stateDict = dictFromString(ss.str());
    }

    scratchTime restartTime("flapFoamTest-rigidBodyDynamics", 1, dt);
    restartTime().setTime(25*dt, 25);
    RBD::eABAMotion restarted(restartTime(), modelDict, stateDict);
    EXPECT_FALSE(restarted.freshStart());
    EXPECT_EQ(restarted.controller()->nUpdates(), 1);

    for (label step = 26; step <= 85; ++step)
    {
        advance(motion, step);
        advance(restarted, step);
        compareStates(restarted.state(), motion.state(), 1e-12, step);
    }
    EXPECT_EQ(motion.controller()->nUpdates(), 4);
    EXPECT_EQ(restarted.controller()->nUpdates(), 4);
    EXPECT_EQ(restarted.controller()->record(), motion.controller()->record());
    EXPECT_EQ(restarted.state().q()[1], motion.state().q()[1]);

    IOstream::defaultPrecision(oldPrecision);
}


TEST(controlTerm, MeasuresOfTheState)
{
    RBD::eABAMotion motion(runTime(), controlledModel());
    RBD::rigidBodyModelState state(motion);
    state.q() = scalarField({0.03, 0.2, -0.1});
    state.qDot() = scalarField({0.5, 0.7, -0.3});
    motion.forwardDynamicsCorrection(state);

    const std::string fuselage("body fuselage; component z; quantity");
    EXPECT_NEAR(measure(motion, fuselage + " position;"), 0.03, 1e-15);
    EXPECT_NEAR(measure(motion, fuselage + " velocity;"), 0.5, 1e-15);

    // Ry joints: pitch = the sum of the joint angles, its rate the sum of
    // their rates
    const std::string link2("body link2; component y; quantity");
    EXPECT_NEAR(measure(motion, link2 + " orientation;"), 0.1, 1e-14);
    EXPECT_NEAR(measure(motion, link2 + " angularVelocity;"), 0.4, 1e-14);
    controlTerm pitch
    (
        motion,
        dictFromString(link2 + " orientation; setPoint 0.1; Kd 1;")
    );
    EXPECT_NEAR(pitch.update(0, 0, true), 0.4, 1e-14);
    EXPECT_NEAR(pitch.error(), 0, 1e-14);

    // derivative mean: the change of the measure since the last update over
    // the time between (here of a velocity, which has no state rate)
    controlTerm accel
    (
        motion,
        dictFromString
        (
            fuselage + " velocity; setPoint 0; Kd 1; derivative mean;"
            " rateSetPoint 0.25;"
        )
    );
    accel.start();
    state.qDot()[0] = 0.8;
    motion.forwardDynamicsCorrection(state);
    EXPECT_NEAR(accel.update(0.1, 0.1, true), (0.8 - 0.5)/0.1 - 0.25, 1e-12);
    EXPECT_NEAR(accel.errorRate(), 2.75, 1e-12);
}


TEST(controlLoop, SaturationAndNoWindUp)
{
    RBD::eABAMotion motion(runTime(), controlledModel());
    const std::string loop
    (
        "entry shoulder; parameter offset; min -1; max 1;"
        " terms { z { body fuselage; quantity position; component z;"
        " setPoint 10; Kp 1; Ki 1; } } saturation "
    );

    const controlLoop tanhLoop
    (
        motion, motion.imposedMotions(), dictFromString(loop + "tanh;")
    );
    EXPECT_EQ(tanhLoop.saturate(0), 0);
    EXPECT_NEAR(tanhLoop.saturate(0.5), std::tanh(0.5), 1e-15);
    EXPECT_GT(tanhLoop.saturate(-30), -1 - 1e-15);
    EXPECT_LT(tanhLoop.saturate(30), 1 + 1e-15);

    controlLoop linear
    (
        motion, motion.imposedMotions(), dictFromString(loop + "linear;")
    );
    EXPECT_EQ(linear.saturate(0.3), 0.3);
    EXPECT_EQ(linear.saturate(-7), -1);
    EXPECT_EQ(linear.saturate(7), 1);

    // e = -10: clipped at -1; the integral stops growing while clipped
    EXPECT_EQ(linear.update(0.01, 0.01), -1);
    const scalar integral = linear.terms()[0].integral();
    EXPECT_NEAR(integral, -0.1, 1e-12);
    EXPECT_EQ(linear.update(0.02, 0.01), -1);
    EXPECT_EQ(linear.terms()[0].integral(), integral);
}


TEST(flightController, BadEntries)
{
    const bool throwing = FatalError.throwExceptions();
    const bool throwingIO = FatalIOError.throwExceptions();

    const std::string loop
    (
        "entry shoulder; parameter amplitude; saturation tanh; min 0.5;"
        " max 1.5; terms { z { body fuselage; quantity position;"
        " component z; setPoint 0; Kp -1; } }"
    );
    auto make = [&](const std::string& base, const std::string& loopText)
    {
        return [=]()
        {
            RBD::eABAMotion m
            (
                runTime(),
                controlledModel(base + " loops { lift { " + loopText + " } }")
            );
        };
    };
    const std::string ok("type PID; update rate; rate 50;");

    expectIOError(make("type bogus; update rate; rate 50;", loop), {"bogus", "PID"});
    expectIOError(make(ok + " gain 1;", loop), {"gain", "allowed keys", "loops"});
    expectIOError(make("type PID; update sometimes;", loop), {"sometimes", "cycle", "rate"});
    expectIOError(make("type PID; update rate; rate 0;", loop), {"rate"});
    expectIOError(make("type PID; update cycle; cycleOf elbow;", loop), {"elbow", "shoulder"});
    expectIOError(make(ok + " blend 2;", loop), {"blend"});
    expectIOError
    (
        [&](){ RBD::eABAMotion m(runTime(), controlledModel(ok + " loops {}")); },
        {"empty"}
    );
    expectIOError(make(ok, "entry elbow; parameter amplitude; saturation tanh; min 0; max 1; terms {}"), {"elbow", "shoulder"});
    expectIOError(make(ok, "entry shoulder; parameter joint; saturation tanh; min 0; max 1; terms {}"), {"joint", "amplitude", "offset"});
    expectIOError(make(ok, "entry shoulder; parameter amplitude; saturation soft; min 0; max 1; terms {}"), {"soft", "tanh", "linear"});
    expectIOError(make(ok, "entry shoulder; parameter amplitude; saturation tanh; min 1; max 1; terms {}"), {"min", "max", "min < max"});
    expectIOError(make(ok, "entry shoulder; parameter amplitude; saturation tanh; min 0; max 1; terms {}"), {"terms", "empty"});

    const std::string head("entry shoulder; parameter amplitude; saturation tanh; min 0; max 1; terms { z { ");
    expectIOError(make(ok, head + "body wing; quantity position; component z; setPoint 0; } }"), {"wing", "not a body of the tree", "fuselage"});
    expectIOError(make(ok, head + "body fuselage; quantity height; component z; setPoint 0; } }"), {"height", "position", "angularVelocity"});
    expectIOError(make(ok, head + "body fuselage; quantity position; component w; setPoint 0; } }"), {"component", "w", "x"});
    expectIOError(make(ok, head + "body fuselage; quantity velocity; component z; setPoint 0; Kd 1; } }"), {"Kd", "velocity", "position and orientation", "derivative mean"});
    expectIOError(make(ok, head + "body fuselage; quantity position; component z; setPoint 0; Kdd 1; } }"), {"Kdd", "allowed keys"});
    expectIOError
    (
        make(ok, loop + " } twice { " + loop),
        {"twice", "shoulder.amplitude", "another loop"}
    );

    FatalError.throwExceptions(throwing);
    FatalIOError.throwExceptions(throwingIO);
}


// ************************************************************************* //
