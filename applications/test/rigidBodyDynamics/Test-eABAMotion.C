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
    flapFoamTest-rigidBodyDynamics: eABAMotion (eABAModel with the imposed
    motions, restraints and time integration):
    - relaxation acts on the free joints only;
    - evaluate() gives the consistent state against the dense oracle;
    - restart from the written model and state continues identically
      (model restart: no composite joint, see models/restart);
    - write() writes g;
    - nIter, accelerationRelaxation and accelerationDamping out of their
      ranges are FatalIOErrors naming the key, the value and the range.

\*---------------------------------------------------------------------------*/

#include "rigidBodyTests.H"
#include "expectError.H"

// * * * * * * * * * * * * * * * eABAMotion tests  * * * * * * * * * * * * * //

// Relaxation: free qdd = aRelax*new + (1 - aRelax)*previous, prescribed
// qdd untouched
TEST(eABAMotion, RelaxationActsOnFreeJointsOnly)
{
    testMotion motion(runTime(), harmonicCase("Newmark", 1, 0.5));

    RBD::rigidBodyModelState state(motion);
    state.t() = 0.0123;
    state.q() = scalarField({0.01, -0.02, 0.1, 0, 0.2, 0, 0});
    state.qDot() = scalarField({0.1, 0.2, -0.3, 0, 0.4, 0, 0});
    state.qDdot() = scalarField({1, -2, 3, 0, -4, 0, 0});
    motion.impose(state);
    motion.forwardDynamicsCorrection(state);

    const scalarField tau(motion.nDoF(), Zero);
    const Field<spatialVector> fx(motion.nBodies(), Zero);

    RBD::rigidBodyModelState unrelaxed(state);
    motion.RBD::eABAModel::forwardDynamics(unrelaxed, tau, fx);

    RBD::rigidBodyModelState relaxed(state);
    motion.forwardDynamics(relaxed, tau, fx);

    for (const label qi : labelList({0, 1, 2, 4}))
    {
        EXPECT_DOUBLE_EQ
        (
            relaxed.qDdot()[qi],
            0.5*unrelaxed.qDdot()[qi] + 0.5*state.qDdot()[qi]
        ) << "q " << qi;
    }
    for (const label qi : motion.prescribed())
    {
        EXPECT_EQ(relaxed.qDdot()[qi], state.qDdot()[qi]) << "q " << qi;
    }
}


// evaluate(): the consistent state (exact prescribed kinematics, free qdd,
// prescribed forces) with the restraints, against the dense oracle
TEST(eABAMotion, EvaluateMatchesDenseOracle)
{
    testMotion motion(runTime(), harmonicCase("symplectic", 1, 1));

    RBD::rigidBodyModelState state(motion);
    state.t() = 0.0371;
    state.q() = scalarField({0.01, -0.02, 0.1, 0, 0.2, 0, 0});
    state.qDot() = scalarField({0.1, 0.2, -0.3, 0, 0.4, 0, 0});

    const scalarField tau({0.1, -0.2, 0.05, 0.3, 0.01, -0.02, 0.03});
    Field<spatialVector> fx(motion.nBodies(), Zero);
    fx[motion.bodyID("wing")] = spatialVector(1e-3, 2e-3, 0, 0.01, 0, 0.02);

    motion.evaluate(state, tau, fx);

    // Applied forces seen by the model: tau, fx plus the restraints
    scalarField rtau(tau);
    Field<spatialVector> rfx(fx);
    motion.applyRestraints(rtau, rfx, state);

    const denseOracle oracle(motion);
    MatX M;
    VecX C;
    oracle.massMatrixAndBias(state.q(), state.qDot(), rfx, M, C);

    scalar x, xd, xdd;
    VecX qdd(VecX::Zero(motion.nDoF()));
    for (const harmonicMotion& h : harmonics)
    {
        h.eval(state.t(), x, xd, xdd);
        EXPECT_NEAR(state.q()[h.q], x, 1e-14*h.A);
        qdd(h.q) = xdd;
    }
    VecX tauP;
    hybridOracle(M, C, toEigen(rtau), motion.prescribed(), qdd, tauP);

    const labelList freeQ(complement(motion.nDoF(), motion.prescribed()));
    EXPECT_LE
    (
        relErr(select(toEigen(state.qDdot()), freeQ), select(qdd, freeQ)),
        1e-10
    );

    VecX tauPeABA(motion.prescribed().size());
    forAll(motion.prescribed(), k)
    {
        tauPeABA(k) =
            motion.prescribedTau()[k] + rtau[motion.prescribed()[k]];
    }
    EXPECT_LE(relErr(tauPeABA, tauP), 1e-10);
}



// Restart: the model written by eABAMotion::write and the state written by
// rigidBodyModelState::write give a model that continues identically
TEST(eABAMotion, RestartFromWrittenDictionary)
{
    // Write at full precision (the default of 6 digits is what the case's
    // writePrecision would give)
    const unsigned oldPrecision = IOstream::defaultPrecision(17);

    RBD::eABAMotion motion(runTime(), readTestModel("restart"));

    const scalarField tau(motion.nDoF(), Zero);
    const Field<spatialVector> fx(motion.nBodies(), Zero);
    const scalar dt = 1e-3;

    auto advance = [&](RBD::eABAMotion& m, const label step)
    {
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

    // Write the model and the state, read them back
    OStringStream os;
    motion.write(os);
    dictionary modelDict(dictFromString(os.str()));

    dictionary stateDict;
    motion.state().write(stateDict);

    // The run restarts at the time of the state
    scratchTime restartTime("flapFoamTest-rigidBodyDynamics", 1, dt);
    restartTime().setTime(20*dt, 20);

    RBD::eABAMotion restarted(restartTime(), modelDict, stateDict);
    EXPECT_FALSE(restarted.freshStart());

    EXPECT_EQ(restarted.nDoF(), motion.nDoF());
    EXPECT_EQ(restarted.prescribed(), motion.prescribed());
    EXPECT_EQ(restarted.nIter(), motion.nIter());
    EXPECT_EQ(restarted.g(), motion.g());
    compareStates(restarted.state(), motion.state(), 0, 20);

    // The previous-time state is not part of the restart data: both take
    // the current state as the previous one
    motion.newTime();
    restarted.newTime();

    for (label step = 21; step <= 40; ++step)
    {
        advance(motion, step);
        advance(restarted, step);
        compareStates(restarted.state(), motion.state(), 1e-12, step);
    }

    IOstream::defaultPrecision(oldPrecision);
}



// Initial state: a state dictionary not written by a step of the run at
// this time is a fresh start (prescribed joints from their motions, free
// accelerations from the eABA); one written by the run is kept as written
TEST(eABAMotion, FreshStartUnlessWrittenByTheRunAtThisTime)
{
    const dictionary modelDict(harmonicCase("symplectic", 1, 1));
    const label n = 7;

    dictionary atRest;
    atRest.add("q", scalarField(n, Zero));
    atRest.add("qDot", scalarField(n, Zero));
    atRest.add("qDdot", scalarField(n, Zero));

    testMotion fresh(runTime(), modelDict, atRest);
    EXPECT_TRUE(fresh.freshStart());
    EXPECT_EQ(fresh.state().t(), runTime().value());

    // The consistent state, computed here
    RBD::rigidBodyModelState consistent(fresh);
    consistent.t() = runTime().value();
    fresh.evaluate
    (
        consistent,
        scalarField(n, Zero),
        Field<spatialVector>(fresh.nBodies(), Zero)
    );
    compareStates(fresh.state(), consistent, 0, 0);
    EXPECT_GT(mag(fresh.state().qDdot()[harmonics[0].q]), 1);

    // Written by a step of the run at this time (t, deltaT > 0): kept
    dictionary written(atRest);
    written.add("t", runTime().value());
    written.add("deltaT", 1e-3);
    testMotion restarted(runTime(), modelDict, written);
    EXPECT_FALSE(restarted.freshStart());
    EXPECT_EQ(restarted.state().qDdot(), scalarField(n, Zero));

    // Written at another time, or before any step (deltaT 0): fresh
    for (const scalar dt : {0.0, 1e-3})
    {
        dictionary other(atRest);
        other.add("t", runTime().value() + 0.5);
        other.add("deltaT", dt);
        testMotion m(runTime(), modelDict, other);
        EXPECT_TRUE(m.freshStart()) << "deltaT " << dt;
        compareStates(m.state(), consistent, 0, 0);
    }
}


// eABAMotion::write mirrors the constructor, which reads g (the stock
// rigidBodyMotion::write does not write g): a model re-read from its
// written dictionary keeps gravity
TEST(eABAMotion, WriteIncludesGravity)
{
    RBD::eABAMotion motion(runTime(), readTestModel("restart"));

    OStringStream os;
    motion.write(os);
    const dictionary written(dictFromString(os.str()));

    ASSERT_TRUE(written.found("g"));
    EXPECT_EQ(written.get<vector>("g"), motion.g());
}



// nIter >= 1, accelerationRelaxation and accelerationDamping in (0, 1]
// (readAllowed): a value outside is refused, the closed end 1 accepted
TEST(eABAMotion, RefusesNumbersOutOfRange)
{
    const bool throwingIO = FatalIOError.throwExceptions();

    expectIOError
    (
        [](){ testMotion m(runTime(), harmonicCase("Newmark", 0, 1)); },
        {"nIter 0:", "a value >= 1 is allowed"}
    );
    for (const scalar a : {0.0, 1.5})
    {
        expectIOError
        (
            [&](){ testMotion m(runTime(), harmonicCase("Newmark", 1, a)); },
            {
                "accelerationRelaxation " + name(a) + ":",
                "a value in (0, 1] is allowed"
            }
        );
    }
    dictionary damped(harmonicCase("Newmark", 1, 1));
    damped.add("accelerationDamping", 0);
    expectIOError
    (
        [&](){ testMotion m(runTime(), damped); },
        {"accelerationDamping 0:", "a value in (0, 1] is allowed"}
    );
    EXPECT_NO_THROW(testMotion m(runTime(), harmonicCase("Newmark", 3, 1)));

    FatalIOError.throwExceptions(throwingIO);
}


// ************************************************************************* //
