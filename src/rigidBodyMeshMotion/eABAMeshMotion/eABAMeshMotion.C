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
\*---------------------------------------------------------------------------*/

#include "eABAMeshMotion.H"
#include "bodyLoad.H"
#include "eABAMeshMotionKeys.H"
#include "addToRunTimeSelectionTable.H"
#include "polyMesh.H"
#include "stepTimers.H"
#include "bitSet.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(eABAMeshMotion, 0);

    addToRunTimeSelectionTable
    (
        motionSolver,
        eABAMeshMotion,
        dictionary
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::eABAMeshMotion::zonePoints
(
    const word& zoneName,
    const dictionary& dict
) const
{
    const label zonei = mesh().cellZones().findZoneID(zoneName);

    if (zonei < 0)
    {
        FatalIOErrorInFunction(dict)
            << "cellZone " << zoneName << " not found; the mesh has "
            << mesh().cellZones().names() << exit(FatalIOError);
    }

    bitSet isZonePoint(mesh().nPoints());
    for (const label celli : mesh().cellZones()[zonei])
    {
        isZonePoint.set(mesh().cellPoints(celli));
    }

    return isZonePoint.sortedToc();
}


void Foam::eABAMeshMotion::readBodies()
{
    const dictionary& bodiesDict = coeffDict().subDict("bodies");

    // Points already owned by a moving zone
    bitSet owned(mesh().nPoints());

    bodyMeshes_.setSize(bodiesDict.size());
    label nBodyMeshes = 0;

    for (const entry& e : bodiesDict)
    {
        if (!e.isDict())
        {
            continue;
        }

        const dictionary& bodyDict = e.dict();
        const bool hasPatches = bodyDict.found("patches");
        const bool hasZone = bodyDict.found("cellZone");

        if (!hasPatches && !hasZone)
        {
            continue;
        }

        if (!hasZone)
        {
            FatalIOErrorInFunction(bodyDict)
                << "body " << e.keyword() << " has patches "
                << flatOutput(bodyDict.get<wordRes>("patches"))
                << " but no cellZone: its"
                << " component mesh would not move with it.  Allowed:"
                << " cellZone <zone of the body's component mesh>, one of "
                << flatOutput(mesh().cellZones().names())
                << exit(FatalIOError);
        }

        // The patches are the load's (bodyLoad); the body is listed
        bodyMesh& bm = bodyMeshes_[nBodyMeshes++];
        bm.name = e.keyword();
        bm.bodyID = bodyLoad::treeBodyID(model_, bm.name, bodyDict);

        bm.cellZone = bodyDict.get<word>("cellZone");
        bm.pointIDs = zonePoints(bm.cellZone, bodyDict);

        for (const label pointi : bm.pointIDs)
        {
            if (owned.test(pointi))
            {
                FatalIOErrorInFunction(bodyDict)
                    << "cellZone " << bm.cellZone << " of body " << bm.name
                    << " shares points with another moving zone:"
                    << " component meshes must be separate"
                    << exit(FatalIOError);
            }
            owned.set(pointi);
        }
    }

    bodyMeshes_.setSize(nBodyMeshes);
}


void Foam::eABAMeshMotion::readBackground()
{
    if (!coeffDict().found("background"))
    {
        return;
    }

    const dictionary& dict = coeffDict().subDict("background");

    // The model's bodyID() of an unknown name is a FatalError of its table:
    // the name is checked here first, with the file and the key
    const word bodyName(dict.get<word>("body"));
    wordList names(model_.nBodies());
    forAll(names, bodyi)
    {
        names[bodyi] = model_.name(bodyi);
    }
    if (!names.found(bodyName))
    {
        FatalIOErrorInFunction(dict)
            << "body " << bodyName << " is not a body of the tree; allowed: "
            << names << exit(FatalIOError);
    }
    backgroundBodyID_ = model_.bodyID(bodyName);

    backgroundMask_ = dict.getOrDefault<vector>("components", vector::one);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (backgroundMask_[d] != 0 && backgroundMask_[d] != 1)
        {
            FatalIOErrorInFunction(dict)
                << "components " << backgroundMask_
                << ": each component must be 0 (fixed) or 1 (follows)"
                << exit(FatalIOError);
        }
    }

    backgroundPointIDs_ = zonePoints(dict.get<word>("cellZone"), dict);

    for (const bodyMesh& bm : bodyMeshes_)
    {
        if (bm.cellZone == dict.get<word>("cellZone"))
        {
            FatalIOErrorInFunction(dict)
                << "cellZone " << bm.cellZone << " is both the background"
                << " and the component of body " << bm.name
                << exit(FatalIOError);
        }
    }
}


Foam::wordList Foam::eABAMeshMotion::keys(const bool topLevel)
{
    // The keys of the model, of the loads (bodyLoad's and its types':
    // patchLoad, aerodynamics) and of the motion solver; at the top level
    // of dynamicMeshDict also those of the dynamic mesh
    wordList k(RBD::eABAMotion::keys());
    k.append(eABAMeshMotionKeys::coeffs(topLevel));
    return k;
}


const Foam::dictionary& Foam::eABAMeshMotion::checked
(
    const dictionary& dict,
    const dictionary& coeffs
)
{
    eABAMeshMotionKeys::check(dict, coeffs);
    return coeffs;
}


const Foam::wordList& Foam::eABAMeshMotion::backgroundKeys()
{
    return eABAMeshMotionKeys::background();
}


Foam::wordList Foam::eABAMeshMotion::bodyNames() const
{
    wordList names(bodyMeshes_.size());
    forAll(bodyMeshes_, i)
    {
        names[i] = bodyMeshes_[i].name;
    }
    return names;
}


void Foam::eABAMeshMotion::updatePoints()
{
    const pointField& p0 = points0();

    for (const bodyMesh& bm : bodyMeshes_)
    {
        // From the reference (zero-state) configuration to the current one
        const spatialTransform X
        (
            model_.X0(bm.bodyID).inv() & model_.X00(bm.bodyID)
        );

        for (const label pointi : bm.pointIDs)
        {
            curPoints_[pointi] = X.transformPoint(p0[pointi]);
        }
    }

    if (backgroundPointIDs_.size())
    {
        // Translation of the followed body's centre of mass from the
        // reference configuration, selected components only
        const label b = backgroundBodyID_;
        const vector d
        (
            cmptMultiply
            (
                backgroundMask_,
                record_->centreOfMass(model_.X0(b), b)
              - record_->centreOfMass(model_.X00(b), b)
            )
        );

        for (const label pointi : backgroundPointIDs_)
        {
            curPoints_[pointi] = p0[pointi] + d;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::eABAMeshMotion::eABAMeshMotion
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    points0MotionSolver(mesh, dict, typeName),
    model_
    (
        mesh.time(),
        checked(dict, coeffDict()),
        RBD::eABAMotion::initialState(mesh, coeffDict())
    ),
    backgroundBodyID_(-1),
    backgroundMask_(Zero),
    curPoints_(points0()),
    curTimeIndex_(-1),
    tau_(model_.nDoF(), Zero),
    fx_(model_.nBodies(), Zero)
{
    readBodies();
    readBackground();
    load_ = bodyLoad::New(mesh, model_, coeffDict(), "patchLoad");
    if (!isA<bodyLoads::aerodynamics>(load_()))
    {
        bodyLoads::aerodynamics::checkEntries(mesh, model_, coeffDict());
    }

    // The model, its bodies and their loads for the output.  The model
    // made a fresh start consistent (eABAMotion: the flow's load at the
    // start is taken as zero, exact for uniform initial p and U); a
    // restart keeps the stored state.
    record_.reset
    (
        new RBD::motionRecord
        (
            mesh, model_, fx_, bodyNames(), model_.freshStart()
        )
    );

    updatePoints();

    model_.writeJointMap(Info);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::eABAMeshMotion::~eABAMeshMotion()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::pointField> Foam::eABAMeshMotion::curPoints() const
{
    return tmp<pointField>(new pointField(curPoints_));
}


void Foam::eABAMeshMotion::solve()
{
    stepTimers::scope timer(stepTimers::New(mesh().time()), "rbd");

    const Time& t = mesh().time();

    if (mesh().nPoints() != points0().size())
    {
        FatalErrorInFunction
            << "the mesh has " << mesh().nPoints() << " points but points0 "
            << points0().size() << ": topology changes are not supported"
            << exit(FatalError);
    }

    // Once per time step: store the state of the previous time
    if (curTimeIndex_ != t.timeIndex())
    {
        model_.newTime();
        curTimeIndex_ = t.timeIndex();
    }

    // The predicted state, then the corrections.  The flow's load is that
    // of the flow's time, the start of the step, once a step (the coupled
    // step is explicit in it: first order in its change over a step); a
    // load of the state (quasi-steady wings) that of each estimate.
    model_.predict(t.value(), t.deltaTValue());
    load_->loads(model_.state(), fx_);

    for (label iter = 0; iter < model_.nIter(); ++iter)
    {
        if (iter && load_->stateDependent())
        {
            load_->loads(model_.state(), fx_);
        }
        model_.solve(t.value(), t.deltaTValue(), tau_, fx_);
    }

    if (model_.report())
    {
        for (const bodyMesh& bm : bodyMeshes_)
        {
            model_.status(bm.bodyID);
        }
    }

    updatePoints();
}


bool Foam::eABAMeshMotion::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
{
    // The state is small: always ascii, full precision
    return model_.writeState(mesh());
}


bool Foam::eABAMeshMotion::read()
{
    if (points0MotionSolver::read())
    {
        model_.read(coeffDict());
        return true;
    }

    return false;
}


// ************************************************************************* //
