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
    flapFoamTest-rigidBodyDynamics: eABAMotion's time integration with each
    of the eABASolvers (Newmark, symplectic, CrankNicolson), nIter 1 and 3,
    with and without acceleration relaxation:
    - no prescribed joint (model everyJoint): Newmark and Crank-Nicolson
      iterated to convergence (nIter 40) equal the stock rigidBodyMotion
      iterated to convergence step by step: the same implicit step, reached
      from eABAMotion's predictor or from stock's old state (at a few
      iterations they differ: stock's is then first order, see
      flapfoam.studies.integrator_order; applications/test/integratorOrder);
    - harmonic imposedMotion (model pendulumAndWing): the prescribed q,
      qDot, qDdot are exact after every step.

\*---------------------------------------------------------------------------*/

#include "rigidBodyTests.H"

// * * * * * * * * * * * * * * eABASolvers tests  * * * * * * * * * * * * * //

namespace
{

struct motionCase
{
    std::string solver;
    label nIter;
    scalar aRelax;
};


// Readable parameter in the test log
void PrintTo(const motionCase& mc, std::ostream* os)
{
    *os << mc.solver << ", nIter " << mc.nIter << ", accelerationRelaxation "
        << mc.aRelax;
}


std::string caseName(const testing::TestParamInfo<motionCase>& info)
{
    return
        info.param.solver + "_nIter" + std::to_string(info.param.nIter)
      + (info.param.aRelax < 1 ? "_relaxed" : "");
}

} // End anonymous namespace


// No prescribed joint, converged implicit steps: eABAMotion == stock
class eABAMotionStock
:
    public testing::TestWithParam<motionCase>
{};


TEST_P(eABAMotionStock, FiftyConvergedStepsEqualStockRigidBodyMotion)
{
    const motionCase& mc = GetParam();

    const dictionary dict
    (
        motionCaseDict("everyJoint", mc.solver, mc.aRelax)
    );
    RBD::rigidBodyMotion stock(runTime(), dict);
    RBD::eABAMotion eaba(runTime(), dict);

    // eABAMotion starts with the accelerations of the dynamics (a fresh
    // start), the stock model with the dictionary's (zero): the same start
    ASSERT_TRUE(eaba.freshStart());
    stock.state().qDdot() = eaba.state().qDdot();

    ASSERT_EQ(stock.nDoF(), 15);
    ASSERT_EQ(eaba.nDoF(), stock.nDoF());
    ASSERT_EQ(eaba.nBodies(), stock.nBodies());
    ASSERT_TRUE(eaba.unitQuaternions());
    ASSERT_EQ(eaba.prescribed().size(), 0);

    scalarField tau(stock.nDoF(), Zero);
    tau[2] = 0.05;
    tau[4] = -0.02;
    Field<spatialVector> fx(stock.nBodies(), Zero);
    // Global frame: moment about the origin, force acting near the drone
    fx[stock.bodyID("drone")] = spatialVector(0.01, -12, -0.02, 0.5, 0, 12);

    const scalarField q0(stock.state().q());
    const scalar dt = 5e-3;

    for (label step = 1; step <= 50; ++step)
    {
        const scalar t = step*dt;

        stock.newTime();
        eaba.newTime();

        for (label iter = 0; iter < mc.nIter; ++iter)
        {
            stock.solve(t, dt, tau, fx);
            eaba.solve(t, dt, tau, fx);
        }

        compareStates(eaba.state(), stock.state(), 1e-11, step);

        for (label bi = 1; bi < stock.nBodies(); ++bi)
        {
            EXPECT_LE(mag(eaba.X0(bi).r() - stock.X0(bi).r()), 1e-11)
                << "body " << bi << " step " << step;
        }

        if (HasFailure())
        {
            FAIL() << "diverged at step " << step;
        }
    }

    // The motion is not trivial
    EXPECT_GT(relErr(stock.state().q(), q0), 0.05);
}


INSTANTIATE_TEST_SUITE_P
(
    Solvers,
    eABAMotionStock,
    testing::Values
    (
        motionCase{"Newmark", 40, 1},
        motionCase{"Newmark", 40, 0.7},
        motionCase{"CrankNicolson", 40, 1},
        motionCase{"CrankNicolson", 40, 0.7}
    ),
    caseName
);


// Harmonic imposedMotion: exact prescribed state after every step
class eABAMotionHarmonic
:
    public testing::TestWithParam<motionCase>
{};


TEST_P(eABAMotionHarmonic, PrescribedStateExactAfterEachStep)
{
    const motionCase& mc = GetParam();

    RBD::eABAMotion motion
    (
        runTime(),
        harmonicCase(mc.solver, mc.nIter, mc.aRelax)
    );

    ASSERT_EQ(motion.nDoF(), 7);
    ASSERT_EQ(motion.prescribed(), labelList({3, 5, 6}));
    ASSERT_EQ(motion.nIter(), mc.nIter);

    const scalarField tau(motion.nDoF(), Zero);
    const Field<spatialVector> fx(motion.nBodies(), Zero);
    const scalar dt = 1e-3;

    // Consistent start: exact prescribed state at t = 0
    motion.state().t() = 0;
    motion.evaluate(motion.state(), tau, fx);

    RBD::rigidBodyModelState exact(motion);

    for (label step = 1; step <= 50; ++step)
    {
        const scalar t = step*dt;

        motion.newTime();
        for (label iter = 0; iter < motion.nIter(); ++iter)
        {
            motion.solve(t, dt, tau, fx);
        }

        const RBD::rigidBodyModelState& s = motion.state();
        ASSERT_EQ(s.t(), t);

        // Bit for bit the motions' own values
        exact.t() = t;
        motion.impose(exact);

        for (const harmonicMotion& h : harmonics)
        {
            EXPECT_EQ(s.q()[h.q], exact.q()[h.q]) << "step " << step;
            EXPECT_EQ(s.qDot()[h.q], exact.qDot()[h.q]) << "step " << step;
            EXPECT_EQ(s.qDdot()[h.q], exact.qDdot()[h.q]) << "step " << step;

            // The analytic formula, written here
            scalar x, xd, xdd;
            h.eval(t, x, xd, xdd);
            const scalar w = 2*M_PI*h.f;
            EXPECT_NEAR(s.q()[h.q], x, 1e-14*h.A);
            EXPECT_NEAR(s.qDot()[h.q], xd, 1e-14*h.A*w);
            EXPECT_NEAR(s.qDdot()[h.q], xdd, 1e-14*h.A*w*w);
        }
    }

    // The free joints responded
    EXPECT_GT(std::abs(motion.state().q()[4]), 1e-4);
    EXPECT_GT(std::abs(motion.state().q()[1]), 1e-7);
}


INSTANTIATE_TEST_SUITE_P
(
    Solvers,
    eABAMotionHarmonic,
    testing::Values
    (
        motionCase{"Newmark", 1, 1},
        motionCase{"Newmark", 3, 0.5},
        motionCase{"symplectic", 1, 1},
        motionCase{"symplectic", 3, 0.5},
        motionCase{"CrankNicolson", 1, 1},
        motionCase{"CrankNicolson", 3, 0.5}
    ),
    caseName
);


// ************************************************************************* //
