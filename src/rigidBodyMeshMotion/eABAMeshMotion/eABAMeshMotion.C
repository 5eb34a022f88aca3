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
#include "addToRunTimeSelectionTable.H"
#include "polyMesh.H"
#include "fvMesh.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "turbulentTransportModel.H"
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
    const polyBoundaryMesh& patches = mesh().boundaryMesh();

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

        const word& name = e.keyword();
        const label bodyID = model_.bodyID(name);

        if (bodyID < 0 || model_.merged(bodyID))
        {
            FatalIOErrorInFunction(bodyDict)
                << "body " << name << " cannot carry patches or a cellZone:"
                << " it is not a body of the tree (merged bodies move with"
                << " their master)" << exit(FatalIOError);
        }

        bodyMesh& bm = bodyMeshes_[nBodyMeshes++];
        bm.name = name;
        bm.bodyID = bodyID;

        if (hasPatches)
        {
            const wordRes patchNames(bodyDict.get<wordRes>("patches"));
            bm.patchIDs = patches.patchSet(patchNames).sortedToc();

            if (bm.patchIDs.empty())
            {
                FatalIOErrorInFunction(bodyDict)
                    << "patches " << patchNames << " of body " << name
                    << " match no patch; the mesh has " << patches.names()
                    << exit(FatalIOError);
            }
        }

        if (hasZone)
        {
            bm.cellZone = bodyDict.get<word>("cellZone");
            bm.pointIDs = zonePoints(bm.cellZone, bodyDict);

            for (const label pointi : bm.pointIDs)
            {
                if (owned.test(pointi))
                {
                    FatalIOErrorInFunction(bodyDict)
                        << "cellZone " << bm.cellZone << " of body " << name
                        << " shares points with another moving zone:"
                        << " component meshes must be separate"
                        << exit(FatalIOError);
                }
                owned.set(pointi);
            }
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

    const word bodyName(dict.get<word>("body"));
    backgroundBodyID_ = model_.bodyID(bodyName);
    if (backgroundBodyID_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "body " << bodyName << " is not a body of the tree"
            << exit(FatalIOError);
    }

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


void Foam::eABAMeshMotion::calcBodyLoads()
{
    fx_ = Zero;

    if (!fluidLoad_)
    {
        return;
    }

    const fvMesh& fvm = refCast<const fvMesh>(mesh());
    const volScalarField& p = fvm.lookupObject<volScalarField>(pName_);
    const volVectorField& U = fvm.lookupObject<volVectorField>(UName_);

    const incompressible::turbulenceModel& turb =
        fvm.lookupObject<incompressible::turbulenceModel>
        (
            incompressible::turbulenceModel::propertiesName
        );

    for (const bodyMesh& bm : bodyMeshes_)
    {
        vector force(Zero);
        vector moment(Zero);

        for (const label patchi : bm.patchIDs)
        {
            const vectorField& Sf = fvm.Sf().boundaryField()[patchi];
            const scalarField& magSf = fvm.magSf().boundaryField()[patchi];
            const vectorField& Cf = fvm.Cf().boundaryField()[patchi];

            // Pressure on the body (Sf points out of the fluid, into the
            // body) and the wall shear rho nuEff dU/dn from the patch
            // normal gradient only
            const vectorField dF
            (
                rhoInf_
               *(
                   p.boundaryField()[patchi]*Sf
                 - turb.nuEff(patchi)*magSf*U.boundaryField()[patchi].snGrad()
                )
            );

            force += sum(dF);
            moment += sum(Cf ^ dF);
        }

        reduce(force, sumOp<vector>());
        reduce(moment, sumOp<vector>());

        fx_[bm.bodyID] = spatialVector(moment, force);
    }
}


Foam::wordList Foam::eABAMeshMotion::loadedBodies() const
{
    wordList names(bodyMeshes_.size());
    forAll(bodyMeshes_, i)
    {
        names[i] = bodyMeshes_[i].name;
    }
    return names;
}


Foam::vector Foam::eABAMeshMotion::centreOfMass
(
    const spatialTransform& X0,
    const label bodyID
) const
{
    // X0 maps global to body coordinates: its inverse places the body's
    // centre of mass in the global frame
    return X0.inv().transformPoint(model_.I(bodyID).c());
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
                centreOfMass(model_.X0(b), b) - centreOfMass(model_.X00(b), b)
            )
        );

        for (const label pointi : backgroundPointIDs_)
        {
            curPoints_[pointi] = p0[pointi] + d;
        }
    }
}


void Foam::eABAMeshMotion::openOutput()
{
    if (!Pstream::master())
    {
        return;
    }

    const Time& runTime = mesh().time();
    const fileName dir
    (
        runTime.globalPath()/"postProcessing"/typeName/runTime.timeName()
    );
    mkDir(dir);

    jointsFile_.reset(new OFstream(dir/"joints.dat"));
    jointsFile_().precision(12);
    model_.writeJointsHeader(jointsFile_());

    bodiesFile_.reset(new OFstream(dir/"bodies.dat"));
    OFstream& os = bodiesFile_();
    os.precision(12);
    os  << "# time";
    for (const bodyMesh& bm : bodyMeshes_)
    {
        const word& b = bm.name;
        os  << ' ' << b << ":cx " << b << ":cy " << b << ":cz"
            << ' ' << b << ":Fx " << b << ":Fy " << b << ":Fz"
            << ' ' << b << ":Mx " << b << ":My " << b << ":Mz";
    }
    os  << nl << "# c: centre of mass; F: fluid force; M: fluid moment about"
        << " the centre of mass; global frame" << endl;
}


void Foam::eABAMeshMotion::writeOutput()
{
    if (!Pstream::master())
    {
        return;
    }

    model_.writeJointsRow(jointsFile_());

    OFstream& os = bodiesFile_();
    os  << model_.state().t();
    for (const bodyMesh& bm : bodyMeshes_)
    {
        const vector c(centreOfMass(bm.bodyID));
        const vector& F = fx_[bm.bodyID].l();
        const vector M(moment(bm.bodyID, c));

        os  << ' ' << c.x() << ' ' << c.y() << ' ' << c.z()
            << ' ' << F.x() << ' ' << F.y() << ' ' << F.z()
            << ' ' << M.x() << ' ' << M.y() << ' ' << M.z();
    }
    os  << endl;
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
        coeffDict(),
        RBD::eABAMotion::initialState(mesh, coeffDict())
    ),
    backgroundBodyID_(-1),
    backgroundMask_(Zero),
    fluidLoad_(coeffDict().getOrDefault<Switch>("fluidLoad", true)),
    rhoInf_(coeffDict().get<scalar>("rhoInf")),
    pName_(coeffDict().getOrDefault<word>("p", "p")),
    UName_(coeffDict().getOrDefault<word>("U", "U")),
    curPoints_(points0()),
    curTimeIndex_(-1),
    tau_(model_.nDoF(), Zero),
    fx_(model_.nBodies(), Zero)
{
    if (rhoInf_ <= 0)
    {
        FatalIOErrorInFunction(coeffDict())
            << "rhoInf " << rhoInf_ << ": must be positive"
            << exit(FatalIOError);
    }

    readBodies();
    readBackground();

    // A fresh start: the exact prescribed state at the start time and
    // consistent accelerations (gravity and restraints: the flow is at
    // rest).  A restart keeps the stored state.
    const bool restart =
        RBD::eABAMotion::stateIO(mesh).typeHeaderOk<IOdictionary>(true);

    if (!restart)
    {
        model_.state().t() = mesh.time().value();
        model_.evaluate(model_.state(), tau_, fx_);
    }

    updatePoints();

    model_.writeJointMap(Info);
    openOutput();

    // The start row of a fresh run; a restart's start row is the last row
    // of the run it continues (with its load)
    if (!restart)
    {
        writeOutput();
    }
}


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
    const bool newStep = (curTimeIndex_ != t.timeIndex());
    if (newStep)
    {
        model_.newTime();
        curTimeIndex_ = t.timeIndex();
    }

    // Fluid load of the flow at the start of the step
    calcBodyLoads();

    for (label iter = 0; iter < model_.nIter(); ++iter)
    {
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

    if (newStep)
    {
        writeOutput();
    }
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
