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

    Trees:
    - SW (single wing, 4 DoF): Pz, Px on massless bodies, then Rz
      (flapping) on a massless body and Ry (pitching) carrying the wing
      (1.5 g, inertia 6e-6, centre of mass at the centre of rotation);
      prescribed: Rz, Ry.
    - BW (body-wing, 5 DoF): Pz, Px on massless bodies, Ry carrying the body
      (1.5 g, inertia 6e-6), then the wing on Rz (massless body), Ry
      (0.15 g, inertia (1e-8 2e-9 1e-8), centre of mass 47.5 mm along the
      span); prescribed: the wing's Rz, Ry.

    Run with bench/forwardDynamics/run for the median of 10 repetitions and
    the markdown table.

\*---------------------------------------------------------------------------*/

#include <benchmark/benchmark.h>

#include "eABAModel.H"
#include "rigidBodyModelState.H"
#include "scratchTime.H"
#include "IStringStream.H"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>
#include <unistd.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * //

namespace
{

std::unique_ptr<scratchTime> runTimePtr;


const char* singleWingDict = R"(
bodies
{
    heave
    {
        type masslessBody; parent root;
        transform (1 0 0 0 1 0 0 0 1) (0 0 0);
        joint { type Pz; }
    }
    surge
    {
        type masslessBody; parent heave;
        transform (1 0 0 0 1 0 0 0 1) (0 0 0);
        joint { type Px; }
    }
    stroke
    {
        type masslessBody; parent surge;
        transform (1 0 0 0 1 0 0 0 1) (0 0 0);
        joint { type Rz; }
    }
    wing
    {
        type rigidBody; parent stroke;
        mass 1.5e-3; centreOfMass (0 0 0); inertia (6e-6 0 0 6e-6 0 6e-6);
        transform (1 0 0 0 1 0 0 0 1) (0 0 0);
        joint { type Ry; }
    }
}
)";


const char* bodyWingDict = R"(
bodies
{
    heave
    {
        type masslessBody; parent root;
        transform (1 0 0 0 1 0 0 0 1) (0 0 0);
        joint { type Pz; }
    }
    surge
    {
        type masslessBody; parent heave;
        transform (1 0 0 0 1 0 0 0 1) (0 0 0);
        joint { type Px; }
    }
    body
    {
        type rigidBody; parent surge;
        mass 1.5e-3; centreOfMass (0 0 0); inertia (6e-6 0 0 6e-6 0 6e-6);
        transform (1 0 0 0 1 0 0 0 1) (0 0 0);
        joint { type Ry; }
    }
    stroke
    {
        // Wing root hinge on the body's surface (radius = chord)
        type masslessBody; parent body;
        transform (1 0 0 0 1 0 0 0 1) (0 0.015 0);
        joint { type Rz; }
    }
    wing
    {
        type rigidBody; parent stroke;
        mass 1.5e-4; centreOfMass (0 0.0475 0); inertia (1e-8 0 0 2e-9 0 1e-8);
        transform (1 0 0 0 1 0 0 0 1) (0 0 0);
        joint { type Ry; }
    }
}
)";


// One tree with its state and forces, set up once
struct droneTree
{
    RBD::eABAModel model;
    RBD::rigidBodyModelState state;
    scalarField tau;
    Field<spatialVector> fx;

    droneTree(const char* dictString, const labelList& prescribed)
    :
        model((*runTimePtr)(), dictionary(IStringStream(dictString)())),
        state(model),
        tau(model.nDoF(), Zero),
        fx(model.nBodies(), Zero)
    {
        // rigidBodyModel does not read g (the motion classes do)
        model.g() = vector(0, 0, -9.81);
        model.setPrescribed(prescribed);

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
    singleWing.reset(new droneTree(singleWingDict, labelList({2, 3})));

    // BW: q = (Pz Px Ry Rz Ry), the wing's Rz, Ry prescribed
    bodyWing.reset(new droneTree(bodyWingDict, labelList({3, 4})));

    // The minimum of the repetitions as well: the least disturbed by other
    // load on the machine
    auto minimum = [](const std::vector<double>& v)
    {
        return *std::min_element(v.begin(), v.end());
    };

    benchmark::RegisterBenchmark("SW_4DoF/eABA", eABA, singleWing.get())
        ->ComputeStatistics("min", minimum);
    benchmark::RegisterBenchmark("SW_4DoF/stock", stock, singleWing.get())
        ->ComputeStatistics("min", minimum);
    benchmark::RegisterBenchmark("BW_5DoF/eABA", eABA, bodyWing.get())
        ->ComputeStatistics("min", minimum);
    benchmark::RegisterBenchmark("BW_5DoF/stock", stock, bodyWing.get())
        ->ComputeStatistics("min", minimum);

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
