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
    flapFoamTest-rigidBodyDynamics: the joint torque of prescribed joints
    whose parameters a controller changes (imposedMotionList::set, blended
    by imposedMotionBlend), on the model pendulumAndWing:
    - inside the blends, the eABA's prescribed-joint torque equals inverse
      dynamics of the dense oracle at the blended q, qDot, qDdot (1e-10);
    - the torque is continuous at the start and end of every blend, a
      change during a running blend included (1e-9), where an abrupt change
      (blend time 0) jumps (the impulsive torque the blend avoids).

\*---------------------------------------------------------------------------*/

#include "rigidBodyTests.H"
#include "imposedMotionList.H"

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

//- The model pendulumAndWing, its imposed motions and a fixed state of the
//- free joints (q 0-2, 4)
struct blendCase
{
    testModel model;
    imposedMotionList motions;
    RBD::rigidBodyModelState state;
    const scalarField tau;
    const Field<spatialVector> fx;

    blendCase()
    :
        model(runTime(), readTestModel("pendulumAndWing")),
        motions(readTestModel("pendulumAndWing"), model.jointDoF()),
        state(model),
        tau(model.nDoF(), Zero),
        fx(model.nBodies(), Zero)
    {
        model.setPrescribed(motions.joints());
    }

    //- The prescribed joints' torque at time t (state set there)
    scalarField torque(const scalar t)
    {
        state.t() = t;
        state.q() = scalarField({0.01, -0.02, 0.1, 0, 0.2, 0, 0});
        state.qDot() = scalarField({0.1, 0.2, -0.3, 0, 0.4, 0, 0});
        state.qDdot() = Zero;
        motions.evaluate(t, state.q(), state.qDot(), state.qDdot());
        model.forwardDynamics(state, tau, fx);
        return model.prescribedTau();
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(imposedMotionBlend, PrescribedTorqueIsInverseDynamicsInsideBlends)
{
    blendCase c;
    const scalar t0 = 0.0371, Tb = 0.0125;
    c.motions.set("stroke", "amplitude", 1.0, t0, Tb);
    c.motions.set("pitch", "frequency", 24, t0 + 0.3*Tb, Tb);
    c.motions.set("shoulder", "offset", -0.5, t0 + 0.1*Tb, 2*Tb);

    const denseOracle oracle(c.model);
    const labelList& prescribed = c.model.prescribed();

    double worst = 0;
    for (label k = 0; k < 40; ++k)
    {
        const scalar t = t0 + 2.5*Tb*(k + 0.5)/40;
        const scalarField tauP(c.torque(t));

        const VecX tauID
        (
            oracle.inverseDynamics
            (
                c.state.q(), c.state.qDot(), toEigen(c.state.qDdot()),
                true, c.fx
            )
        );
        const double err = relErr(toEigen(tauP), select(tauID, prescribed));
        worst = std::max(worst, err);
        EXPECT_LE(err, 1e-10) << "t = " << t;
    }
    Info<< "Prescribed torque inside blends: worst relative error against"
        << " inverse dynamics " << worst << endl;
}


TEST(imposedMotionBlend, PrescribedTorqueContinuousAcrossUpdates)
{
    const scalar t0 = 0.0371, Tb = 0.0125, t1 = t0 + 0.3*Tb;
    const scalar h = 1e-12*Tb;

    blendCase c;
    c.motions.set("stroke", "amplitude", 1.0, t0, Tb);
    c.motions.set("stroke", "frequency", 24, t1, Tb);

    for (const scalar tc : {t0, t1, t0 + Tb, t1 + Tb})
    {
        EXPECT_LE(relErr(c.torque(tc - h), c.torque(tc + h)), 1e-9)
            << "torque jumps at t = " << tc;
    }

    // An abrupt change: the torque jumps
    blendCase abrupt;
    abrupt.motions.set("stroke", "amplitude", 1.0, t0, 0);
    EXPECT_GT(relErr(abrupt.torque(t0 - h), abrupt.torque(t0 + h)), 1e-2);
}


// Restart in the middle of a blend: the model written by eABAMotion::write,
// the state written as eABAMotion::writeState writes it (the motion state
// and imposedMotionList::writeState) give a run that continues as the
// uninterrupted one, the controller's changes after the restart included
TEST(eABAMotion, RestartInTheMiddleOfABlend)
{
    const unsigned oldPrecision = IOstream::defaultPrecision(17);

    RBD::eABAMotion motion(runTime(), readTestModel("restart"));

    const scalarField tau(motion.nDoF(), Zero);
    const Field<spatialVector> fx(motion.nBodies(), Zero);
    const scalar dt = 1e-3;

    // A controller: a change every 8 steps, blended over 12
    auto advance = [&](RBD::eABAMotion& m, const label step)
    {
        if (step % 8 == 0)
        {
            m.imposedMotions().set
            (
                "shoulder", step % 16 ? "amplitude" : "frequency",
                1 + 0.01*step, (step - 1)*dt, 12*dt
            );
        }
        m.newTime();
        for (label iter = 0; iter < m.nIter(); ++iter)
        {
            m.solve(step*dt, dt, tau, fx);
        }
    };

    for (label step = 1; step <= 20; ++step)
    {
        advance(motion, step);
    }
    ASSERT_TRUE(motion.imposedMotions().blend("shoulder").blending(20*dt));

    OStringStream os;
    motion.write(os);
    dictionary modelDict(dictFromString(os.str()));

    dictionary stateDict;
    motion.state().write(stateDict);
    motion.imposedMotions().writeState(stateDict);

    scratchTime restartTime("flapFoamTest-rigidBodyDynamics", 1, dt);
    restartTime().setTime(20*dt, 20);

    RBD::eABAMotion restarted(restartTime(), modelDict, stateDict);
    EXPECT_FALSE(restarted.freshStart());
    EXPECT_EQ(restarted.imposedMotions().blend("shoulder").nStages(), 3);
    compareStates(restarted.state(), motion.state(), 0, 20);

    motion.newTime();
    restarted.newTime();

    for (label step = 21; step <= 60; ++step)
    {
        advance(motion, step);
        advance(restarted, step);
        compareStates(restarted.state(), motion.state(), 1e-12, step);
        const label j = 1;
        EXPECT_EQ(restarted.state().q()[j], motion.state().q()[j]);
        EXPECT_EQ(restarted.state().qDdot()[j], motion.state().qDdot()[j]);
    }

    IOstream::defaultPrecision(oldPrecision);
}


// ************************************************************************* //
