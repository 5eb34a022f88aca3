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
    flapFoamTest-rigidBodyDynamics: eABAModel (the extended articulated-body
    algorithm) on random trees and states:
    - no prescribed joint: forwardDynamics equals the stock
      rigidBodyModel::forwardDynamics of the same object;
    - random prescribed subsets: the free qdd and the prescribed joint
      forces against the dense oracle's partition of M qdd + C = tau
      (docs/paper.md section 1);
    - all joints prescribed: prescribedTau is inverse dynamics, and the
      stock ABA driven by it gives back the prescribed qdd;
    - invalid prescribed sets and a tree changed after setPrescribed are
      errors.

\*---------------------------------------------------------------------------*/

#include "rigidBodyTests.H"

// * * * * * * * * * * * * * * * eABAModel tests * * * * * * * * * * * * * //

// No prescribed joint: eABA == stock ABA on the same object
TEST(eABAModel, NoPrescribedEqualsStockABA)
{
    randomSource rnd(1);
    double worst = 0;

    for (label trial = 0; trial < 200; ++trial)
    {
        testModel model(runTime());
        const std::vector<label> types =
            buildRandomTree(model, rnd, jointSet::all);

        // Half with an explicit empty prescribed set, half never set
        if (trial % 2)
        {
            model.setPrescribed(labelList());
        }
        model.g() = rnd.vec(-10, 10);

        RBD::rigidBodyModelState state(model);
        randomState(model, rnd, state);
        const scalarField tau(randomField(rnd, model.nDoF()));
        const Field<spatialVector> fx
        (
            (trial % 7 == 0)
          ? Field<spatialVector>()
          : randomForces(rnd, model.nBodies())
        );

        RBD::rigidBodyModelState stock(state);
        RBD::rigidBodyModelState eaba(state);

        model.RBD::rigidBodyModel::forwardDynamics(stock, tau, fx);
        model.forwardDynamics(eaba, tau, fx);

        const double err = relErr(eaba.qDdot(), stock.qDdot());
        worst = std::max(worst, err);
        EXPECT_LE(err, 1e-12)
            << "tree " << trial << " " << describeTree(model, types);
        EXPECT_EQ(model.prescribedTau().size(), 0);
    }

    RecordProperty("worstRelErr", std::to_string(worst));
    Info<< "200 trees: worst relative difference eABA - stock " << worst
        << endl;
}


// Random prescribed subsets of the 1-DoF joints, all joint types in the
// tree (3-DoF, composite, floating and quaternion joints free)
TEST(eABAModel, PrescribedSubsetMatchesDenseOracle)
{
    randomSource rnd(3);
    double worstQdd = 0;
    double worstTau = 0;
    label nPrescribedTotal = 0;
    label nFreeTotal = 0;
    label nFree3DoF = 0;
    label maxDoF = 0;
    label maxDepth = 0;
    label nQuaternionTrees = 0;

    for (label trial = 0; trial < 200; ++trial)
    {
        testModel model(runTime());
        const std::vector<label> types =
            buildRandomTree(model, rnd, jointSet::all);
        model.g() = rnd.vec(-10, 10);

        // Random subset, with a random density (none to all)
        const labelList candidates(prescribableQ(model));
        const scalar density = rnd.integer(0, 4)/4.0;
        DynamicList<label> chosen;
        for (const label qi : candidates)
        {
            if (rnd.coin(density))
            {
                chosen.append(qi);
            }
        }
        const labelList prescribed(std::move(chosen));
        model.setPrescribed(prescribed);
        ASSERT_EQ(model.prescribed(), prescribed);

        for (label i = 1; i < model.nBodies(); ++i)
        {
            if (model.joints()[i].nDoF() == 3) ++nFree3DoF;
        }
        maxDoF = max(maxDoF, model.nDoF());
        maxDepth = max(maxDepth, treeDepth(model));
        if (model.unitQuaternions()) ++nQuaternionTrees;

        RBD::rigidBodyModelState state(model);
        randomState(model, rnd, state);
        const scalarField tau(randomField(rnd, model.nDoF()));
        const Field<spatialVector> fx(randomForces(rnd, model.nBodies()));

        RBD::rigidBodyModelState eaba(state);
        model.forwardDynamics(eaba, tau, fx);

        // Oracle
        const denseOracle oracle(model);
        MatX M;
        VecX C;
        oracle.massMatrixAndBias(state.q(), state.qDot(), fx, M, C);
        VecX qdd(toEigen(state.qDdot()));
        VecX tauP;
        hybridOracle(M, C, toEigen(tau), prescribed, qdd, tauP);

        const labelList freeQ(complement(model.nDoF(), prescribed));
        nPrescribedTotal += prescribed.size();
        nFreeTotal += freeQ.size();

        // Prescribed accelerations are input: untouched
        for (const label qi : prescribed)
        {
            EXPECT_EQ(eaba.qDdot()[qi], state.qDdot()[qi]);
        }

        const double errQdd =
            relErr(select(toEigen(eaba.qDdot()), freeQ), select(qdd, freeQ));

        ASSERT_EQ(model.prescribedTau().size(), prescribed.size());
        VecX tauPeABA(prescribed.size());
        forAll(prescribed, k)
        {
            tauPeABA(k) = model.prescribedTau()[k] + tau[prescribed[k]];
        }
        const double errTau = relErr(tauPeABA, tauP);

        worstQdd = std::max(worstQdd, errQdd);
        worstTau = std::max(worstTau, errTau);

        EXPECT_LE(errQdd, 1e-10)
            << "tree " << trial << " " << describeTree(model, types);
        EXPECT_LE(errTau, 1e-10)
            << "tree " << trial << " " << describeTree(model, types);
    }

    // The random trees did exercise both kinds of joint
    EXPECT_GT(nPrescribedTotal, 200);
    EXPECT_GT(nFreeTotal, 200);
    EXPECT_GT(nFree3DoF, 50);

    RecordProperty("worstRelErrQdd", std::to_string(worstQdd));
    RecordProperty("worstRelErrTau", std::to_string(worstTau));

    Info<< "200 trees: " << nPrescribedTotal << " prescribed and "
        << nFreeTotal << " free q, " << nFree3DoF << " free 3-DoF joints, "
        << nQuaternionTrees << " trees with a quaternion joint, up to "
        << maxDoF << " DoF, depth up to " << maxDepth
        << "; worst relative error qdd " << worstQdd << ", tau "
        << worstTau << endl;
}


// Every joint prescribed: prescribedTau + tau = inverse dynamics, and the
// stock ABA driven by that force reproduces the prescribed qdd
TEST(eABAModel, AllPrescribedIsInverseDynamics)
{
    randomSource rnd(4);
    double worstTau = 0;
    double worstQdd = 0;

    for (label trial = 0; trial < 150; ++trial)
    {
        testModel model(runTime());
        const std::vector<label> types =
            buildRandomTree(model, rnd, jointSet::oneDoF);
        model.g() = rnd.vec(-10, 10);

        const labelList all(identity(model.nDoF()));
        ASSERT_EQ(prescribableQ(model).size(), model.nDoF());
        model.setPrescribed(all);

        RBD::rigidBodyModelState state(model);
        randomState(model, rnd, state);
        const scalarField tau(randomField(rnd, model.nDoF()));
        const Field<spatialVector> fx(randomForces(rnd, model.nBodies()));

        RBD::rigidBodyModelState eaba(state);
        model.forwardDynamics(eaba, tau, fx);

        const scalarField tauTotal(model.prescribedTau() + tau);

        const denseOracle oracle(model);
        const VecX tauID
        (
            oracle.inverseDynamics
            (
                state.q(), state.qDot(), toEigen(state.qDdot()), true, fx
            )
        );

        const double errTau = relErr(toEigen(tauTotal), tauID);
        worstTau = std::max(worstTau, errTau);
        EXPECT_LE(errTau, 1e-10)
            << "tree " << trial << " " << describeTree(model, types);

        // Stock ABA, all joints free, driven by the recovered force
        RBD::rigidBodyModelState stock(state);
        stock.qDdot() = Zero;
        model.RBD::rigidBodyModel::forwardDynamics(stock, tauTotal, fx);

        const double errQdd = relErr(stock.qDdot(), state.qDdot());
        worstQdd = std::max(worstQdd, errQdd);
        EXPECT_LE(errQdd, 1e-10)
            << "tree " << trial << " " << describeTree(model, types);

        // Power of the actuators
        const scalarField power(model.prescribedPower(eaba));
        forAll(all, k)
        {
            EXPECT_EQ(power[k], model.prescribedTau()[k]*state.qDot()[k]);
        }
    }

    RecordProperty("worstRelErrTau", std::to_string(worstTau));
    RecordProperty("worstRelErrQdd", std::to_string(worstQdd));
    Info<< "150 trees: worst relative error tau " << worstTau
        << ", stock ABA qdd " << worstQdd << endl;
}


// Invalid prescribed sets and a tree changed after setPrescribed are errors
TEST(eABAModel, RejectsInvalidPrescribedSets)
{
    const bool throwing = FatalError.throwExceptions();

    testModel model(runTime());
    const label b1 = model.join
    (
        0,
        spatialTransform(),
        autoPtr<RBD::joint>(new RBD::joints::Rxyz()),
        autoPtr<RBD::rigidBody>
        (
            new RBD::rigidBody("a", 1, Zero, symmTensor(1, 0, 0, 1, 0, 1))
        )
    );
    model.join
    (
        b1,
        spatialTransform(),
        autoPtr<RBD::joint>(new RBD::joints::Ry()),
        autoPtr<RBD::rigidBody>
        (
            new RBD::rigidBody("b", 1, Zero, symmTensor(1, 0, 0, 1, 0, 1))
        )
    );

    // q 0..2: Rxyz (3 DoF), q 3: Ry
    EXPECT_THROW(model.setPrescribed(labelList({1})), Foam::error);
    EXPECT_THROW(model.setPrescribed(labelList({4})), Foam::error);
    EXPECT_THROW(model.setPrescribed(labelList({-1})), Foam::error);
    EXPECT_THROW(model.setPrescribed(labelList({3, 3})), Foam::error);
    EXPECT_NO_THROW(model.setPrescribed(labelList({3})));

    EXPECT_EQ(model.jointDoF(), labelList({3, 3, 3, 1}));

    // Grow the tree after setPrescribed
    model.join
    (
        b1,
        spatialTransform(),
        autoPtr<RBD::joint>(new RBD::joints::Px()),
        autoPtr<RBD::rigidBody>
        (
            new RBD::rigidBody("c", 1, Zero, symmTensor(1, 0, 0, 1, 0, 1))
        )
    );
    RBD::rigidBodyModelState state(model);
    const scalarField tau(model.nDoF(), Zero);
    EXPECT_THROW
    (
        model.forwardDynamics(state, tau, Field<spatialVector>()),
        Foam::error
    );

    FatalError.throwExceptions(throwing);
}


// ************************************************************************* //
