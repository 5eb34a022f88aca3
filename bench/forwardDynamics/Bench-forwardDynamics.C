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

Application
    flapFoamBench-forwardDynamics

Description
    Google Benchmark of one forward-dynamics call on the drone trees of the
    paper (docs/paper.md section 3), side by side on the same model object and
    state:
    - eABA: eABAModel::forwardDynamics with the wing joints prescribed;
    - stock: rigidBodyModel::forwardDynamics (ABA, all joints free).

    Trees: the eABAMeshMotionCoeffs of the cases' own dictionaries (bodies,
    g, and the prescribed joints: those of imposedMotion), read from
    cases/<case>/constant/dynamicMeshDict.eABA (path set at build time):
    - SW (singleWingDrone, 4 DoF): Pz, Px on massless bodies, then Rz
      (flapping) on a massless body and Ry (pitching) carrying the wing;
      prescribed: Rz, Ry;
    - BW (bodyWingDrone, 5 DoF): Pz, Px on massless bodies, Ry carrying the
      body, then the wing on Rz (massless body), Ry; prescribed: the wing's
      Rz, Ry.

    Run with bench/forwardDynamics/run for the median of 10 repetitions and
    the markdown table.

\*---------------------------------------------------------------------------*/

#include <benchmark/benchmark.h>

#include "eABAModel.H"
#include "rigidBodyModelState.H"
#include "scratchTime.H"
#include "imposedMotionList.H"
#include "IFstream.H"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>
#include <unistd.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * //

namespace
{

std::unique_ptr<scratchTime> runTimePtr;


//- The drone cases' multibody dictionaries (FLAPFOAM_CASES: Make/options)
const fileName singleWingDict
(
    fileName(FLAPFOAM_CASES)/"singleWingDrone/constant/dynamicMeshDict.eABA"
);
const fileName bodyWingDict
(
    fileName(FLAPFOAM_CASES)/"bodyWingDrone/constant/dynamicMeshDict.eABA"
);


//- The eABAMeshMotionCoeffs of a case's dynamicMeshDict
dictionary motionCoeffs(const fileName& dynamicMeshDict)
{
    IFstream is(dynamicMeshDict);
    if (!is.good())
    {
        FatalErrorInFunction
            << "cannot read " << dynamicMeshDict << exit(FatalError);
    }
    return dictionary(is).subDict("eABAMeshMotionCoeffs");
}


// One tree with its state and forces, set up once
struct droneTree
{
    RBD::eABAModel model;
    RBD::rigidBodyModelState state;
    scalarField tau;
    Field<spatialVector> fx;

    explicit droneTree(const dictionary& coeffs)
    :
        model((*runTimePtr)(), coeffs),
        state(model),
        tau(model.nDoF(), Zero),
        fx(model.nBodies(), Zero)
    {
        // rigidBodyModel reads neither g nor the imposed motions (the
        // motion classes do)
        model.g() = coeffs.get<vector>("g");
        model.setPrescribed
        (
            imposedMotionList(coeffs, model.jointDoF()).joints()
        );

        // A mid-stroke state: all joints moving, wing accelerating, an
        // aerodynamic force on the wing (global frame)
        forAll(state.q(), i)
        {
            state.q()[i] = 0.1*(i + 1);
            state.qDot()[i] = 0.5 - 0.2*i;
            state.qDdot()[i] = 100*(i + 1);
        }
        fx[model.nBodies() - 1] =
            spatialVector(1e-5, -2e-5, 3e-5, 5e-3, -1e-3, 2e-2);

        check();
    }

    //- The timed call does the work: the stock ABA driven by the joint
    //- forces the eABA returns gives back the prescribed accelerations
    void check()
    {
        RBD::rigidBodyModelState eaba(state);
        model.forwardDynamics(eaba, tau, fx);

        scalarField tauTotal(tau);
        forAll(model.prescribed(), k)
        {
            tauTotal[model.prescribed()[k]] += model.prescribedTau()[k];
        }

        RBD::rigidBodyModelState stock(state);
        model.RBD::rigidBodyModel::forwardDynamics(stock, tauTotal, fx);

        const scalar err = max(mag(stock.qDdot() - eaba.qDdot()));
        if (err > 1e-9*max(mag(eaba.qDdot())))
        {
            FatalErrorInFunction
                << "eABA and stock ABA disagree: qDdot " << eaba.qDdot()
                << " and " << stock.qDdot() << exit(FatalError);
        }
    }
};


std::unique_ptr<droneTree> singleWing;
std::unique_ptr<droneTree> bodyWing;


void eABA(benchmark::State& st, droneTree* tree)
{
    for (auto _ : st)
    {
        tree->model.forwardDynamics(tree->state, tree->tau, tree->fx);
        benchmark::DoNotOptimize(tree->state.qDdot().cdata());
        benchmark::ClobberMemory();
    }
}


void stock(benchmark::State& st, droneTree* tree)
{
    // Its own state: stock ABA overwrites every qDdot
    RBD::rigidBodyModelState state(tree->state);

    for (auto _ : st)
    {
        tree->model.RBD::rigidBodyModel::forwardDynamics
        (
            state,
            tree->tau,
            tree->fx
        );
        benchmark::DoNotOptimize(state.qDdot().cdata());
        benchmark::ClobberMemory();
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * //

int main(int argc, char** argv)
{
    runTimePtr.reset
    (
        new scratchTime("flapFoamBench-forwardDynamics", 1, 1e-5)
    );

    // SW: q = (Pz Px Rz Ry), the wing's Rz, Ry prescribed
    singleWing.reset(new droneTree(motionCoeffs(singleWingDict)));

    // BW: q = (Pz Px Ry Rz Ry), the wing's Rz, Ry prescribed
    bodyWing.reset(new droneTree(motionCoeffs(bodyWingDict)));

    // The minimum of the repetitions as well: the least disturbed by other
    // load on the machine
    auto minimum = [](const std::vector<double>& v)
    {
        return *std::min_element(v.begin(), v.end());
    };

    // Named after the tree and its number of DoF read from the case
    for
    (
        const auto& named
      : {std::make_pair("SW_", singleWing.get()),
         std::make_pair("BW_", bodyWing.get())}
    )
    {
        const std::string tree
        (
            named.first + std::to_string(named.second->model.nDoF()) + "DoF"
        );
        benchmark::RegisterBenchmark((tree + "/eABA").c_str(), eABA,
            named.second)->ComputeStatistics("min", minimum);
        benchmark::RegisterBenchmark((tree + "/stock").c_str(), stock,
            named.second)->ComputeStatistics("min", minimum);
    }

    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
    {
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();

    singleWing.reset();
    bodyWing.reset();
    runTimePtr.reset();

    return 0;
}


// ************************************************************************* //
