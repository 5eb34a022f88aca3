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
    gravity, restraints and the loads that need no flow (bodyLoad vacuum or
    aerodynamics: quasi-steady wings, evaluated at the predicted state and
    at each correction's, so that the step is second order; with
    -staggeredLoads once a step at the state of its start, as the overset
    solver takes the flow's load: first order).  The same model and the same dictionaries as the
    overset mesh motion solver, so the dynamics can be checked quickly and
    a drone flown with quasi-steady wings.

    Reads
      - constant/dynamicMeshDict (or -dict FILE): the multibody dictionary
        (solver, nIter, accelerationRelaxation, accelerationDamping, g,
        bodies, restraints, imposedMotion: see eABAMotion) at the top level,
        in eABAMeshMotionCoeffs (flapFoam's overset motion solver) or in a
        sub-dictionary of solvers (the paper authors' layout; -solver NAME
        chooses if several have bodies): see multibodyDict; the loads:
        -bodyLoad TYPE, else its bodyLoad when that needs no flow (not
        patchLoad), else vacuum;
      - system/controlDict: startTime, endTime, deltaT, writeControl and
        writeInterval (deltaT and writeInterval > 0, endTime not before the
        start time: FatalIOError otherwise);
      - <startTime>/uniform/rigidBodyMotionState when present: the initial
        state, else the multibody dictionary's q and qDot (zero where
        absent; as the overset mesh motion solver); a state not written by
        a step of a run at this time (or none) is a fresh start
        (eABAMotion), made consistent here with the loads of the initial
        state.

    Writes
      - the q-index -> body/joint map to the log;
      - postProcessing/rigidBodySimulate/<startTime>/joints.dat: a header
            # time q_0 qDot_0 qDdot_0 q_1 ... tau_<j> power_<j>
        (tau, power for each prescribed joint j: the actuator force on top
        of the applied joint force, and tau*qDot) and one row per write
        time, including startTime, flushed as it is written;
      - <endTime>/uniform/rigidBodyMotionState: the state to restart from;
      - what the function objects of controlDict write (functions: the
        drone cases' flightData, stepTimers, runProgress), executed after
        every step as in a flow run: the model, its bodies and their loads
        are published (RBD::motionRecord) on a registry region0 without a
        mesh, so flightData writes the flow runs' file,
            postProcessing/flightData/<startTime>/flightData.h5,
        for the bodies with patches or a cellZone (those of a flow run)
        and those carrying a wing of the aerodynamics entry; force and
        moment: the load of the step's last sub-iteration (the wing's
        aerodynamic load; zero on a body without one), coefficients with
        the reference values of the flightData entry; timers: "rbd" is the
        step's multibody solve (stamped as a flow run's mesh update).  The functionObjectProperties
        state dictionary is not written (no time folder but the end's);
        -noFunctionObjects runs none.

Usage
    \b rigidBodySimulate [-case DIR] [-dict FILE] [-solver NAME]
        [-bodyLoad vacuum|aerodynamics] [-staggeredLoads] [-noFunctionObjects]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "IFstream.H"
#include "eABAMotion.H"
#include "multibodyDict.H"
#include "runInputCheck.H"
#include "bodyLoad.H"
#include "aerodynamics.H"
#include "motionRecord.H"
#include "stepTimers.H"
#include "polyMesh.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

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


// A dictionary with an aerodynamics block whose loads are not aerodynamics
// (bodyLoad absent, patchLoad, vacuum or fluidLoad off): the block is not
// used, say so (the user who wrote it expects it used)
void warnUnusedAerodynamics(const dictionary& modelDict, const word& type)
{
    if (type != "aerodynamics" && modelDict.found("aerodynamics"))
    {
        IOWarningInFunction(modelDict)
            << "The aerodynamics block of " << modelDict.name()
            << " is not used: the loads are " << type << " (bodyLoad "
            << modelDict.getOrDefault<word>("bodyLoad", "vacuum (absent)")
            << ", fluidLoad "
            << modelDict.getOrDefault<Switch>("fluidLoad", true)
            << "; patchLoad needs the flow).  To fly with the quasi-steady"
            << " wings: -bodyLoad aerodynamics, or bodyLoad aerodynamics;"
            << " in the dictionary" << endl;
    }
}


// The bodies' loads: -bodyLoad TYPE, else the dictionary's bodyLoad when it
// needs no flow (patchLoad does: then none, as with fluidLoad off; an unused
// aerodynamics block is warned about)
struct appliedLoads
{
    autoPtr<bodyLoad> load;
    Field<spatialVector> fx;

    //- The loads of each estimate of the new state (a load of the state,
    //- bodyLoad::stateDependent, without -staggeredLoads), or once a step,
    //- of the state at its start (as the flow's in the overset solver)
    bool eachEstimate;

    appliedLoads
    (
        const Time& runTime,
        const RBD::rigidBodyModel& model,
        const dictionary& modelDict,
        const argList& args
    )
    :
        fx(model.nBodies(), Zero),
        eachEstimate(false)
    {
        // The loads without a flow: none (vacuum) by default, and for a
        // dictionary written for the CFD (patchLoad: the flow's load)
        const bool fluid = modelDict.getOrDefault<Switch>("fluidLoad", true);
        word type(modelDict.getOrDefault<word>("bodyLoad", "vacuum"));
        if (!fluid || type == "patchLoad")
        {
            type = "vacuum";
        }
        if (!args.readIfPresent("bodyLoad", type))
        {
            warnUnusedAerodynamics(modelDict, type);
        }
        if (type == "patchLoad")
        {
            FatalErrorInFunction
                << "-bodyLoad patchLoad: the flow's load needs the flow;"
                << " rigidBodySimulate runs without a mesh (allowed: vacuum,"
                << " aerodynamics)" << exit(FatalError);
        }

        dictionary dict(modelDict);
        dict.set("bodyLoad", type);
        dict.set("fluidLoad", true);
        load = bodyLoad::New(runTime, model, dict, "vacuum");
        if (type != bodyLoads::aerodynamics::typeName)
        {
            bodyLoads::aerodynamics::checkEntries(runTime, model, modelDict);
        }
        const bool staggered = args.found("staggeredLoads");
        eachEstimate = load->stateDependent() && !staggered;
        Info<< "Loads: " << type
            << (type == "vacuum" ? " (gravity and restraints only)" : "")
            << (staggered ? ", once a step: of the state at its start" : "")
            << nl << endl;
    }

    //- The loads of a state
    const Field<spatialVector>& of(const RBD::rigidBodyModelState& state)
    {
        load->loads(state, fx);
        return fx;
    }
};


// Initial state: <startTime>/uniform/rigidBodyMotionState if present, else
// the multibody dictionary's q and qDot (zero where absent), as the overset
// mesh motion solver takes them; reported to the log
dictionary readInitialState(const Time& runTime, const dictionary& modelDict)
{
    IOobject stateIO(RBD::eABAMotion::stateIO(runTime));
    const bool restart = stateIO.typeHeaderOk<IOdictionary>(false);
    const dictionary stateDict
    (
        RBD::eABAMotion::initialState(runTime, modelDict)
    );

    if (restart)
    {
        Info<< "Initial state from " << stateIO.objectPath() << nl << endl;
    }
    else
    {
        Info<< "No " << stateIO.objectPath() << ": the initial state of "
            << modelDict.name() << " (q, qDot; zero where absent)"
            << nl << endl;
    }

    return stateDict;
}


// The start: a fresh start (eABAMotion) is made consistent again with the
// loads of the initial state (the model took none); a restart keeps the
// stored state and only evaluates the prescribed joints' forces
void initialiseState
(
    RBD::eABAMotion& model,
    const scalarField& tau,
    appliedLoads& loads
)
{
    const Field<spatialVector>& fx = loads.of(model.state());
    if (model.freshStart())
    {
        model.evaluate(model.state(), tau, fx);
    }
    else
    {
        RBD::rigidBodyModelState s(model.state());
        model.evaluate(s, tau, fx);
        model.forwardDynamicsCorrection(model.state());
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


// The bodies the output reports, in the order of the bodies dictionary:
// those with patches or a cellZone (a flow run's: the same datasets) and
// those that carry a wing of the aerodynamics entry
wordList reportedBodies(const dictionary& modelDict)
{
    wordHashSet wings;
    const dictionary* aero = modelDict.findDict("aerodynamics");
    if (aero)
    {
        for (const entry& e : *aero)
        {
            if (e.isDict())
            {
                wings.insert(e.dict().get<word>("body"));
            }
        }
    }

    DynamicList<word> names;
    for (const entry& e : modelDict.subDict("bodies"))
    {
        if
        (
            e.isDict()
         && (
                e.dict().found("patches")
             || e.dict().found("cellZone")
             || wings.found(e.keyword())
            )
        )
        {
            names.append(e.keyword());
        }
    }
    return wordList(std::move(names));
}


// The model, its bodies and their loads for controlDict's function objects
// (flightData), on a registry region0 without a mesh
struct publishedMotion
{
    objectRegistry region;
    RBD::motionRecord record;

    publishedMotion
    (
        const Time& runTime,
        const RBD::eABAMotion& model,
        const appliedLoads& loads,
        const dictionary& modelDict
    )
    :
        region
        (
            IOobject
            (
                polyMesh::defaultRegion,
                runTime.timeName(),
                runTime,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            )
        ),
        record
        (
            region, model, loads.fx, reportedBodies(modelDict),
            model.freshStart()
        )
    {}
};


// The function objects of a step, as functionObjectList::execute but for
// the state dictionary it writes at every write time (a time folder each)
void executeFunctionObjects(Time& runTime)
{
    functionObjectList& functions = runTime.functionObjects();
    for (label i = 0; i < functions.size(); ++i)
    {
        functions[i].execute();
        functions[i].write();
    }
}


// Plain time loop (not Time::run(), see executeFunctionObjects): each step
// solved (the "rbd" step timer), its function objects, its row of
// joints.dat at a write time
void timeLoop
(
    Time& runTime,
    RBD::eABAMotion& model,
    const scalarField& tau,
    appliedLoads& loads,
    OFstream& os
)
{
    const scalar endTime = runTime.endTime().value();

    while (runTime.value() < endTime - 0.5*runTime.deltaTValue())
    {
        ++runTime;

        // The solve in place of a flow run's mesh update (its stamps: the
        // step timers' pimple column is then the function objects before
        // stepTimers, their preUpdate the loop's own work)
        stepTimers& timers = stepTimers::New(runTime);
        timers.stamp(stepTimers::meshUpdateStart);
        {
            stepTimers::scope timer(timers, "rbd");

            // The loads of the step's start, or of each estimate of the
            // new state (the predicted one, then the last correction's)
            model.newTime();
            if (!loads.eachEstimate)
            {
                loads.of(model.state());
            }
            model.predict(runTime.value(), runTime.deltaTValue());
            for (label iter = 0; iter < model.nIter(); ++iter)
            {
                if (loads.eachEstimate)
                {
                    loads.of(model.state());
                }
                model.solve
                (
                    runTime.value(), runTime.deltaTValue(), tau, loads.fx
                );
            }
        }
        timers.stamp(stepTimers::meshUpdated);

        executeFunctionObjects(runTime);

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
        " gravity, restraints and loads that need no flow."
    );
    argList::noParallel();
    multibodyDict::addOptions();
    argList::addBoolOption
    (
        "staggeredLoads",
        "the loads once a step, of the state at its start, as the flow's"
        " load in the overset solver (explicit coupling: first order in the"
        " loads' change over a step); default: the loads of each estimate"
        " of the new state (second order)"
    );
    argList::addOption
    (
        "bodyLoad",
        "type",
        "the bodies' loads: vacuum, or aerodynamics (the wings of the"
        " dictionary's aerodynamics entry); default: the dictionary's"
        " bodyLoad when it needs no flow, else vacuum"
    );

    #include "setRootCase.H"

    // Before Time reads them (writeInterval 0 is a sigFpe there, deltaT 0
    // an endless loop here, 1e400 a sigFpe in the tokenizer)
    runInputCheck::check(args, {"constant/dynamicMeshDict"});

    #include "createTime.H"

    checkEndTime(runTime);

    const multibodyDict multibody(runTime, args);
    const dictionary& modelDict = multibody.dict();

    const dictionary stateDict(readInitialState(runTime, modelDict));

    RBD::eABAMotion model(runTime, modelDict, stateDict);

    model.writeJointMap(Info);
    Info<< nl << "Prescribed q indices: " << model.prescribed() << nl
        << "Integrator: " << modelDict.subDict("solver").get<word>("type")
        << ", nIter " << model.nIter() << nl << endl;

    const scalarField tau(model.nDoF(), Zero);
    appliedLoads loads(runTime, model, modelDict, args);

    model.state().t() = runTime.value();
    initialiseState(model, tau, loads);

    const publishedMotion published(runTime, model, loads, modelDict);
    runTime.functionObjects().start();

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

    timeLoop(runTime, model, tau, loads, os);

    runTime.functionObjects().end();
    model.writeState(runTime);

    Info<< nl << "Wrote " << os.name() << nl
        << "Wrote " << runTime.timeName()/"uniform"/"rigidBodyMotionState"
        << nl << nl << "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
