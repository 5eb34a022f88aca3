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
    oversetMotionCheck

Group
    grpFlapFoamUtilities

Description
    Moves an overset mesh through its motion (constant/dynamicMeshDict) from
    the start time to the end time of system/controlDict, with no flow
    solution, and checks the overset assembly at every time step: per zone
    the calculated, interpolated and hole cells, and the interpolated cells
    left with an empty donor stencil.  A mesh layout that only works at
    some poses shows here in minutes instead of hours into a run: acceptors
    without donors turn into holes and the fringe walk of the stencil
    carries the holes through a zone (a "hole cascade").

    Stops before it reads the case (FatalError naming the option, the value
    and the range) at a bad option value, at a number beyond the range of a
    double in system/controlDict or constant/dynamicMeshDict, at deltaT or
    writeInterval <= 0 (runInputCheck), and before the first step when the
    motion takes the flow's load (eABAMeshMotion with fluidLoad on).

    Fails (exit 1) at the first step where a zone's holes exceed
    -maxHoleFraction of its cells (default 0.25) or an interpolated cell
    has no donor; the last line says which.  Writes the mesh and cellTypes
    at the write times of system/controlDict and at the failing step (to
    look at the poses).

    The motion is the one the solver would compute with no fluid load: for
    eABAMeshMotion set fluidLoad off in its coefficients (the drone cases'
    Allrun does that with -motionOnly).  With -couplings (serial) it also
    collects the donor-acceptor pairs of every step and, if the check
    passes, writes them to constant/oversetCouplings (oversetCouplings) for
    the oversetGraph decomposition method; every K-th step's stencil
    (-sampleEvery, default 10) is kept whole there.  The function objects of
    system/controlDict run as in a solver (the drone cases: flight data,
    joints.dat/bodies.dat, step timers), unless -noFunctionObjects.

Usage
    \b oversetMotionCheck [-maxHoleFraction F] [-couplings [-sampleEvery K]]
        [-noFunctionObjects] [-parallel]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "dynamicFvMesh.H"
#include "cellCellStencilObject.H"
#include "oversetCouplings.H"
#include "runInputCheck.H"
#include "Switch.H"

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Per-zone counts summed over the ranks
void sumOverRanks(labelList& counts)
{
    Pstream::listCombineGather(counts, plusEqOp<label>());
    Pstream::listCombineScatter(counts);
}


// A motion that takes the flow's load cannot be moved without a flow:
// FatalIOError for eABAMeshMotion with the patch load (fields p, U) in
// constant/dynamicMeshDict (its top level, or each entry of solvers)
void checkNoFlowLoad(const Time& runTime)
{
    const IOdictionary meshDict
    (
        IOobject
        (
            "dynamicMeshDict",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    DynamicList<const dictionary*> solverDicts(1, &meshDict);
    if (meshDict.isDict("solvers"))
    {
        solverDicts.clear();
        for (const entry& e : meshDict.subDict("solvers"))
        {
            if (e.isDict())
            {
                solverDicts.append(&e.dict());
            }
        }
    }

    for (const dictionary* d : solverDicts)
    {
        const word solver(d->getOrDefault<word>("motionSolver", word::null));
        const dictionary& coeffs = d->optionalSubDict(solver + "Coeffs");
        if
        (
            solver == "eABAMeshMotion"
         && coeffs.getOrDefault<Switch>("fluidLoad", true)
         && coeffs.getOrDefault<word>("bodyLoad", "patchLoad") == "patchLoad"
        )
        {
            FatalIOErrorInFunction(coeffs)
                << "fluidLoad on: the bodies take the flow's load (fields p"
                << " and U), and oversetMotionCheck solves no flow.  Set"
                << " fluidLoad off in " << coeffs.dictName() << " for this"
                << " check (the drone cases: Allrun -motionOnly does it)"
                << exit(FatalIOError);
        }
    }
}


// Cells per zone, summed over the ranks
labelList countZoneCells(const labelUList& zoneID, const label nZones)
{
    labelList zoneCells(nZones, Zero);
    forAll(zoneID, celli)
    {
        ++zoneCells[zoneID[celli]];
    }
    sumOverRanks(zoneCells);

    return zoneCells;
}


// The overset assembly of one step, summed over the ranks
struct stepCounts
{
    //- Interpolated cells per zone
    labelList nInterp;

    //- Hole cells per zone
    labelList nHoles;

    //- Interpolated cells with an empty donor stencil
    label nOrphans;

    //- Count the cell types of the mesh's current stencil
    stepCounts(const fvMesh& mesh, const labelUList& zoneID, label nZones)
    :
        nInterp(nZones, Zero),
        nHoles(nZones, Zero),
        nOrphans(0)
    {
        const cellCellStencilObject& overlap = Stencil::New(mesh);
        const labelUList& types = overlap.cellTypes();
        const labelListList& stencil = overlap.cellStencil();

        forAll(types, celli)
        {
            if (types[celli] == cellCellStencil::INTERPOLATED)
            {
                ++nInterp[zoneID[celli]];
                if (stencil[celli].empty())
                {
                    ++nOrphans;
                }
            }
            else if (types[celli] == cellCellStencil::HOLE)
            {
                ++nHoles[zoneID[celli]];
            }
        }
        sumOverRanks(nInterp);
        sumOverRanks(nHoles);
        reduce(nOrphans, sumOp<label>());
    }
};


// Log the step's counts, update maxHoles and check the limits: true (with
// the reason logged) if the step fails
bool checkStep
(
    const Time& runTime,
    const stepCounts& counts,
    const labelUList& zoneCells,
    const scalar maxHoleFraction,
    labelList& maxHoles
)
{
    const labelList& nHoles = counts.nHoles;
    bool failed = false;

    Info<< "Time = " << runTime.timeName()
        << " interpolated " << counts.nInterp
        << " holes " << nHoles
        << " no-donor " << counts.nOrphans << endl;

    forAll(nHoles, zonei)
    {
        maxHoles[zonei] = max(maxHoles[zonei], nHoles[zonei]);
        if (nHoles[zonei] > maxHoleFraction*zoneCells[zonei])
        {
            Info<< "oversetMotionCheck: FAILED at time "
                << runTime.timeName() << ": zone " << zonei << " has "
                << nHoles[zonei] << " holes of " << zoneCells[zonei]
                << " cells (more than -maxHoleFraction "
                << maxHoleFraction << ")" << endl;
            failed = true;
        }
    }
    if (counts.nOrphans)
    {
        Info<< "oversetMotionCheck: FAILED at time "
            << runTime.timeName() << ": " << counts.nOrphans
            << " interpolated cells without donors" << endl;
        failed = true;
    }

    return failed;
}

// The note and the options of the command line
void addOptions()
{
    argList::addNote
    (
        "Move an overset mesh through its motion with no flow solution and"
        " check the overset assembly (holes per zone, acceptors without"
        " donors) at every time step"
    );
    argList::addOption
    (
        "maxHoleFraction",
        "F",
        "fail when the holes of a zone exceed this fraction of its cells"
        " (default 0.25)"
    );

    argList::addBoolOption
    (
        "couplings",
        "collect the donor-acceptor pairs of every step into"
        " constant/oversetCouplings (serial; for method oversetGraph)"
    );
    argList::addOption
    (
        "sampleEvery",
        "K",
        "with -couplings: keep every K-th step's stencil whole (default 10)"
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    addOptions();
    #include "setRootCase.H"

    // The options and the input the stock readers do not survive, before
    // they read
    const scalar maxHoleFraction = runInputCheck::option<scalar>
    (
        args, "maxHoleFraction", 0.25, scalarMinMax(VSMALL, 1),
        "a fraction in (0, 1]"
    );
    const label sampleEvery = runInputCheck::option<label>
    (
        args, "sampleEvery", 10, labelMinMax(1, labelMax),
        "an integer >= 1"
    );
    runInputCheck::check(args, wordList({"constant/dynamicMeshDict"}));

    #include "createTime.H"
    checkNoFlowLoad(runTime);
    #include "createDynamicFvMesh.H"

    const labelIOList& zoneID = cellCellStencil::zoneID(mesh);
    const label nZones = returnReduce(max(zoneID) + 1, maxOp<label>());

    const labelList zoneCells(countZoneCells(zoneID, nZones));
    Info<< "Zones (cells): " << zoneCells << nl << endl;

    autoPtr<oversetCouplings> couplings;
    if (args.found("couplings"))
    {
        couplings.reset
        (
            new oversetCouplings(mesh, sampleEvery)
        );
    }
    labelList maxHoles(nZones, Zero);
    label nSteps = 0;
    bool failed = false;

    while (!failed && runTime.run())
    {
        ++runTime;
        mesh.update();
        ++nSteps;

        const stepCounts counts(mesh, zoneID, nZones);
        if (couplings)
        {
            couplings->addPose(mesh);
        }
        failed =
            checkStep(runTime, counts, zoneCells, maxHoleFraction, maxHoles);

        if (failed)
        {
            runTime.writeNow();
        }
        else
        {
            runTime.write();
        }
    }

    Info<< nl << "Steps: " << nSteps << ", largest holes per zone: "
        << maxHoles << " of " << zoneCells << " cells" << nl;
    if (!failed)
    {
        if (couplings)
        {
            couplings->writeCouplings();
        }
        Info<< "oversetMotionCheck: OK" << nl;
    }
    Info<< nl << "End" << nl << endl;

    return failed ? 1 : 0;
}


// ************************************************************************* //
