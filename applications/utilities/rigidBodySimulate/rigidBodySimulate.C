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
    rigidBodySimulate

Group
    grpFlapFoamUtilities

Description
    Runs a multibody model with prescribed joints (eABA) without a mesh:
    gravity and restraints are the only loads.  The same model and the same
    dictionaries as the overset mesh motion solver, so the dynamics can be
    checked quickly.

    Reads
      - constant/dynamicMeshDict (or -dict FILE): the multibody dictionary
        (solver, nIter, accelerationRelaxation, accelerationDamping, g,
        bodies, restraints, imposedMotion: see eABAMotion) at the top level,
        in eABAMeshMotionCoeffs (flapFoam's overset motion solver) or in a
        sub-dictionary of solvers (the paper authors' layout; -solver NAME
        chooses if several have bodies): see multibodyDict;
      - system/controlDict: startTime, endTime, deltaT, writeControl and
        writeInterval (deltaT and writeInterval > 0, endTime not before the
        start time: FatalIOError otherwise);
      - <startTime>/uniform/rigidBodyMotionState when present: the initial
        q, qDot (and qDdot) lists; zero otherwise.  Without qDdot the
        initial accelerations are computed from the state.

    Writes
      - the q-index -> body/joint map to the log;
      - postProcessing/rigidBodySimulate/<startTime>/joints.dat: a header
            # time q_0 qDot_0 qDdot_0 q_1 ... tau_<j> power_<j>
        (tau, power for each prescribed joint j: the actuator force on top
        of the applied joint force, and tau*qDot) and one row per write
        time, including startTime, flushed as it is written;
      - <endTime>/uniform/rigidBodyMotionState: the state to restart from.

Usage
    \b rigidBodySimulate [-case DIR] [-dict FILE] [-solver NAME]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "IFstream.H"
#include "eABAMotion.H"
#include "multibodyDict.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

// Before Time reads system/controlDict (writeInterval 0 is a sigFpe there,
// deltaT 0 an endless loop here): deltaT and writeInterval must be > 0
void checkControlDict(const argList& args)
{
    const fileName file(args.path()/"system"/"controlDict");

    if (!isFile(file))
    {
        return;     // Time says so
    }

    IFstream is(file);
    const dictionary dict(is);

    for (const word key : {"deltaT", "writeInterval"})
    {
        // Missing: Time says so
        const scalar value = dict.getOrDefault<scalar>(key, 1);

        if (!(value > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << key << "' = " << value << " in " << file
                << " is out of range: allowed " << key << " > 0" << nl
                << exit(FatalIOError);
        }
    }
}


// endTime not before the start time (startTime or the latest time)
void checkEndTime(const Time& runTime)
{
    const scalar endTime = runTime.endTime().value();

    if (endTime < runTime.value() - 0.5*runTime.deltaTValue())
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Entry 'endTime' = " << endTime << " in "
            << runTime.controlDict().name()
            << " is before the start time " << runTime.timeName()
            << ": allowed endTime >= " << runTime.timeName() << nl
            << exit(FatalIOError);
    }
}


// Initial state: <startTime>/uniform/rigidBodyMotionState if present (zero
// otherwise), reported to the log
dictionary readInitialState(const Time& runTime)
{
    IOobject stateIO(RBD::eABAMotion::stateIO(runTime));
    const bool restart = stateIO.typeHeaderOk<IOdictionary>(false);
    const dictionary stateDict
    (
        RBD::eABAMotion::initialState(runTime, dictionary())
    );

    if (restart)
    {
        Info<< "Initial state from " << stateIO.objectPath() << nl << endl;
    }
    else
    {
        Info<< "No " << stateIO.objectPath() << ": zero initial state"
            << nl << endl;
    }

    return stateDict;
}


// Consistent state at the start: exact prescribed joints, free
// accelerations and the prescribed joints' forces.  A restart keeps the
// stored accelerations (the next step starts from them, as a run that
// did not stop) and only evaluates the forces; a state without qDdot
// gets consistent accelerations.
void initialiseState
(
    RBD::eABAMotion& model,
    const dictionary& stateDict,
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    if (stateDict.found("qDdot"))
    {
        RBD::rigidBodyModelState s(model.state());
        model.evaluate(s, tau, fx);
        model.forwardDynamicsCorrection(model.state());
    }
    else
    {
        model.evaluate(model.state(), tau, fx);
    }
}


// At a write time: the row of joints.dat, q to the log and the bodies'
// status if the model reports
void writeTime
(
    const Time& runTime,
    const RBD::eABAMotion& model,
    OFstream& os
)
{
    model.writeJointsRow(os);
    Info<< "Time = " << runTime.timeName()
        << "  q = " << model.state().q() << endl;

    if (model.report())
    {
        for (label bodyID = 1; bodyID < model.nBodies(); ++bodyID)
        {
            model.status(bodyID);
        }
    }
}


// Plain time loop: Time::run() would execute the function objects and
// write their state dictionary at every write time
void timeLoop
(
    Time& runTime,
    RBD::eABAMotion& model,
    const scalarField& tau,
    const Field<spatialVector>& fx,
    OFstream& os
)
{
    const scalar endTime = runTime.endTime().value();

    while (runTime.value() < endTime - 0.5*runTime.deltaTValue())
    {
        ++runTime;

        model.newTime();
        for (label iter = 0; iter < model.nIter(); ++iter)
        {
            model.solve(runTime.value(), runTime.deltaTValue(), tau, fx);
        }

        if (runTime.writeTime())
        {
            writeTime(runTime, model, os);
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Run a multibody model with prescribed joints (eABA) without a mesh:"
        " gravity and restraints only."
    );
    argList::noParallel();
    multibodyDict::addOptions();

    #include "setRootCase.H"

    checkControlDict(args);

    #include "createTime.H"

    checkEndTime(runTime);

    const multibodyDict multibody(runTime, args);
    const dictionary& modelDict = multibody.dict();

    const dictionary stateDict(readInitialState(runTime));

    RBD::eABAMotion model(runTime, modelDict, stateDict);

    model.writeJointMap(Info);
    Info<< nl << "Prescribed q indices: " << model.prescribed() << nl
        << "Integrator: " << modelDict.subDict("solver").get<word>("type")
        << ", nIter " << model.nIter() << nl << endl;

    // Gravity and restraints only
    const scalarField tau(model.nDoF(), Zero);
    const Field<spatialVector> fx(model.nBodies(), Zero);

    model.state().t() = runTime.value();
    initialiseState(model, stateDict, tau, fx);

    // Output table
    const fileName outputDir
    (
        runTime.globalPath()/"postProcessing"/"rigidBodySimulate"
       /runTime.timeName()
    );
    mkDir(outputDir);
    OFstream os(outputDir/"joints.dat");
    os.precision(15);

    model.writeJointsHeader(os);
    model.writeJointsRow(os);

    Info<< "Starting time loop" << nl << endl;

    timeLoop(runTime, model, tau, fx, os);

    model.writeState(runTime);

    Info<< nl << "Wrote " << os.name() << nl
        << "Wrote " << runTime.timeName()/"uniform"/"rigidBodyMotionState"
        << nl << nl << "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
