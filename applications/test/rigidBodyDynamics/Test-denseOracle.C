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
    flapFoamTest-rigidBodyDynamics: the dense oracle (denseOracle.H) itself,
    checked first against the stock ABA on random trees: M symmetric and
    qdd = M^-1 (tau - C).

\*---------------------------------------------------------------------------*/

#include "rigidBodyTests.H"

// * * * * * * * * * * * * * * * denseOracle tests  * * * * * * * * * * * * * //

// The oracle's conventions: qdd = M^-1 (tau - C) == stock ABA, M symmetric
TEST(denseOracle, MatchesStockABA)
{
    randomSource rnd(2);
    double worst = 0;

    for (label trial = 0; trial < 200; ++trial)
    {
        testModel model(runTime());
        const std::vector<label> types =
            buildRandomTree(model, rnd, jointSet::all);
        model.g() = rnd.vec(-10, 10);

        RBD::rigidBodyModelState state(model);
        randomState(model, rnd, state);
        const scalarField tau(randomField(rnd, model.nDoF()));
        const Field<spatialVector> fx(randomForces(rnd, model.nBodies()));

        model.RBD::rigidBodyModel::forwardDynamics(state, tau, fx);

        const denseOracle oracle(model);
        MatX M;
        VecX C;
        oracle.massMatrixAndBias(state.q(), state.qDot(), fx, M, C);

        EXPECT_LE((M - M.transpose()).cwiseAbs().maxCoeff(),
            1e-12*M.cwiseAbs().maxCoeff())
            << "tree " << trial << " " << describeTree(model, types);

        const VecX qdd(M.ldlt().solve(toEigen(tau) - C));
        const double err = relErr(qdd, toEigen(state.qDdot()));
        worst = std::max(worst, err);
        EXPECT_LE(err, 1e-10)
            << "tree " << trial << " " << describeTree(model, types);
    }

    RecordProperty("worstRelErr", std::to_string(worst));
    Info<< "200 trees: worst relative difference oracle - stock " << worst
        << endl;
}


// ************************************************************************* //
