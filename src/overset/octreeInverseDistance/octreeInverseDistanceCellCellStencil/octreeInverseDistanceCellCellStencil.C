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

#include "octreeInverseDistanceCellCellStencil.H"
#include "addToRunTimeSelectionTable.H"
#include "dynamicOversetFvMesh.H"
#include "oversetFvPatch.H"
#include "oversetFvPatchField.H"
#include "globalIndex.H"
#include "referencePoints.H"
#include "mapDistribute.H"
#include "stepTimers.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace cellCellStencils
{
    defineTypeNameAndDebug(octreeInverseDistance, 0);
    addToRunTimeSelectionTable(cellCellStencil, octreeInverseDistance, mesh);
}
}

const Foam::word
Foam::cellCellStencils::octreeInverseDistance::stencilPart("oversetStencil");


const Foam::scalar
Foam::cellCellStencils::octreeInverseDistance::residualMargin(4);

const Foam::scalar
Foam::cellCellStencils::octreeInverseDistance::radiusTolerance(1e-6);

const Foam::scalar
Foam::cellCellStencils::octreeInverseDistance::roundOffResidual(1e-12);

const Foam::scalar
Foam::cellCellStencils::octreeInverseDistance::candidateRoundOff(1e-9);

const Foam::word
Foam::cellCellStencils::octreeInverseDistance::orphanSetName
(
    "octreeInverseDistanceOrphans"
);

const Foam::label
Foam::cellCellStencils::octreeInverseDistance::nOrphansShown(5);

const Foam::word
Foam::cellCellStencils::octreeInverseDistance::emptyStencilField
(
    "octreeInverseDistanceCellTypes"
);


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::cellCellStencils::octreeInverseDistance::countZones
(
    const labelUList& zoneID
)
{
    return returnReduce
    (
        zoneID.size() ? max(zoneID) + 1 : 0,
        maxOp<label>()
    );
}


bool Foam::cellCellStencils::octreeInverseDistance::cacheStale() const
{
    return returnReduce
    (
        zoneSearch_.empty()
     || cacheNCells_ != mesh_.nCells()
     || mesh_.topoChanging(),
        orOp<bool>()
    );
}


void Foam::cellCellStencils::octreeInverseDistance::buildZone
(
    const label zonei,
    const labelList& zoneID
)
{
    // Search first: it refers to the sub-mesh
    zoneSearch_.set(zonei, nullptr);
    zoneParts_.set(zonei, new fvMeshSubset(mesh_, zonei, zoneID));

    const fvMesh& subMesh = zoneParts_[zonei].subMesh();
    zoneSearch_.set(zonei, new zoneDonorSearch(subMesh, settings_.maxWalk()));

    prevDonor_[zonei] = labelList(mesh_.nCells(), -1);
    prevRemote_[zonei] = List<labelPair>(mesh_.nCells(), labelPair(-1, -1));

    // Every rank's box of its part of the zone, in the zone's frame
    List<treeBoundBox>& procBb = procBb_[zonei];
    procBb.setSize(Pstream::nProcs());
    procBb[Pstream::myProcNo()] = zoneSearch_[zonei].bb();
    Pstream::gatherList(procBb);
    Pstream::scatterList(procBb);

    // Bounding radius of each zone cell about its centre
    const labelList& cellMap = zoneParts_[zonei].cellMap();
    const pointField& points = mesh_.points();
    const pointField& cc = mesh_.cellCentres();
    const cellList& cells = mesh_.cells();
    const faceList& faces = mesh_.faces();

    scalarField& radius = cellRadius_[zonei];
    radius.setSize(cellMap.size());
    forAll(cellMap, i)
    {
        const label celli = cellMap[i];
        scalar r2 = 0;
        for (const label facei : cells[celli])
        {
            for (const label pointi : faces[facei])
            {
                r2 = max(r2, magSqr(points[pointi] - cc[celli]));
            }
        }
        radius[i] = Foam::sqrt(r2);
    }

    bins_[zonei].build(subMesh.cellCentres(), radius);

    if (zonei == settings_.searchBoxFollows())
    {
        readFollowPoints0(zonei);
    }
}


void Foam::cellCellStencils::octreeInverseDistance::readFollowPoints0
(
    const label zonei
)
{
    followPoints0_ = referencePoints
    (
        mesh_,
        zoneParts_[zonei].pointMap(),
        "searchBoxFollows " + Foam::name(zonei)
    );
    followMin0_ = boundBox(followPoints0_, true).min();

    Info<< type() << " : searchBox " << settings_.searchBox()
        << " (at the reference points) follows the translation of zone "
        << zonei << endl;
}


void Foam::cellCellStencils::octreeInverseDistance::followZone()
{
    const label zonei = settings_.searchBoxFollows();
    if (zonei < 0)
    {
        return;
    }

    // The lower corner of the zone's box: a min over the points, the same
    // bits on every rank and in serial
    const labelList& pointMap = zoneParts_[zonei].pointMap();
    const pointField& points = mesh_.points();
    searchBoxShift_ = boundBox(points, pointMap, true).min() - followMin0_;

    scalar deviation = 0;
    forAll(pointMap, i)
    {
        deviation =
            max
            (
                deviation,
                mag(points[pointMap[i]] - followPoints0_[i] - searchBoxShift_)
            );
    }
    reduce(deviation, maxOp<scalar>());

    const scalar allowed = settings_.rigidTolerance()*zoneSearch_[zonei].size();
    if (deviation > allowed)
    {
        FatalIOErrorInFunction(dict_)
            << "searchBoxFollows " << zonei << ": zone " << zonei
            << " does not move by a pure translation at time "
            << mesh_.time().timeName() << " (a point is " << deviation
            << " from the translation " << searchBoxShift_
            << " of its reference point, more than rigidTolerance*size "
            << allowed << "): follow a zone that only translates (the"
            << " background of eABAMeshMotion), or leave searchBoxFollows"
            << " out (a fixed box)" << exit(FatalIOError);
    }
}


Foam::treeBoundBox
Foam::cellCellStencils::octreeInverseDistance::currentSearchBox() const
{
    const treeBoundBox& bb = settings_.searchBox();
    return treeBoundBox(bb.min() + searchBoxShift_, bb.max() + searchBoxShift_);
}


void Foam::cellCellStencils::octreeInverseDistance::buildCache
(
    const labelList& zoneID
)
{
    const label nZones = countZones(zoneID);

    zoneSearch_.clear();
    zoneParts_.clear();
    zoneSearch_.setSize(nZones);
    zoneParts_.setSize(nZones);
    prevDonor_.setSize(nZones);
    prevRemote_.setSize(nZones);
    procBb_.setSize(nZones);
    cellRadius_.setSize(nZones);
    bins_.setSize(nZones);
    zoneResidual_.setSize(nZones, Zero);
    nearlyRigidSaid_ = boolList(nZones, false);

    // Voxel maps: refilled at the next update
    localVoxels_ = List<patchVoxelMap>(nZones);
    patchFilledSmallVec_.setSize(nZones, Zero);
    patchFilledPoints_.setSize(nZones);
    patchVoxels_.setSize(nZones);
    voxelExchange_.clear(nZones);

    for (label zonei = 0; zonei < nZones; ++zonei)
    {
        buildZone(zonei, zoneID);
    }
    cacheNCells_ = mesh_.nCells();
    fullReason_ = "cache built";

    Info<< type() << " : built the search cache of " << nZones
        << " zones in their own frames at time " << mesh_.time().timeName()
        << endl;
}


bool Foam::cellCellStencils::octreeInverseDistance::nearlyRigid
(
    const label zonei
) const
{
    return zoneResidual_[zonei] > roundOffResidual*zoneSearch_[zonei].size();
}


Foam::label Foam::cellCellStencils::octreeInverseDistance::currentDonor
(
    const label srcI,
    const point& p,
    const label srcCelli
) const
{
    if (!nearlyRigid(srcI))
    {
        return srcCelli;
    }
    return
        zoneSearch_[srcI].currentCell
        (
            mesh_, zoneParts_[srcI].cellMap(), p, srcCelli
        );
}


void Foam::cellCellStencils::octreeInverseDistance::lap(const char* part)
{
    const stepTimers::clock::time_point now = stepTimers::clock::now();
    timers_.add(word(stencilPart + part), stepTimers::seconds(lapStart_, now));
    lapStart_ = now;
}


void Foam::cellCellStencils::octreeInverseDistance::fitZones()
{
    const labelList& zoneID = this->zoneID();
    const pointField& points = mesh_.points();

    forAll(zoneSearch_, zonei)
    {
        const scalar residual =
            zoneSearch_[zonei].fitTransform
            (
                points, zoneParts_[zonei].pointMap()
            );
        zoneResidual_[zonei] = residual;
        const scalar size = zoneSearch_[zonei].size();

        if (residual > settings_.rigidTolerance()*size)
        {
            WarningInFunction
                << "zone " << zonei << " is not rigid: point residual "
                << residual << " > rigidTolerance*size "
                << settings_.rigidTolerance()*size
                << "; rebuilding its search cache"
                << endl;
            buildZone(zonei, zoneID);
            fullReason_ = "zone " + Foam::name(zonei) + " rebuilt";
        }
        else if (nearlyRigid(zonei) && !nearlyRigidSaid_[zonei])
        {
            nearlyRigidSaid_[zonei] = true;
            Info<< type() << " : zone " << zonei << " moves only nearly"
                << " rigidly (rigid-fit residual " << residual
                << " = " << residual/size << " of its size, above"
                << " round-off " << roundOffResidual << ", below"
                << " rigidTolerance " << settings_.rigidTolerance() << "): its"
                << " donors are checked against the current points" << endl;
        }
        if (nearlyRigid(zonei))
        {
            // The current-point checks (also of a rebuilt zone) use the
            // mesh's tet base points: collective when first built (the
            // residual is the same on every rank)
            (void)mesh_.tetBasePtIs();
        }

        treeBoundBox& zoneBb = ws_.zoneBb[zonei][0];
        const boundBox bb(points, zoneParts_[zonei].pointMap(), true);
        if (!bb.empty())
        {
            zoneBb = treeBoundBox(bb);
        }
        else
        {
            // As the stock stencil: a box outside the mesh
            const boundBox& allBb = mesh_.bounds();
            zoneBb =
                treeBoundBox
                (
                    allBb.min() - 2*allBb.span(),
                    allBb.min() - allBb.span()
                );
        }
        zoneBb.inflate(1e-6);
    }

    followZone();
}


void Foam::cellCellStencils::octreeInverseDistance::updateCached()
{
    if (cacheStale())
    {
        buildCache(zoneID());
    }
    ws_.reset(mesh_.nCells(), zoneSearch_.size());
    smallVec_ = mesh_.bounds().span()*settings_.tolerance();

    // Laps of the update as nested stepTimers parts (oversetStencil keeps
    // the rest: cache building, logging)
    lapStart_ = stepTimers::clock::now();

    fitZones();
    lap("Transform");

    fillVoxels();
    lap("Voxels");

    cutHoles();
    lap("Holes");

    findAllDonors();
    lap("Donors");

    classifyCells();
    lap("Flood");

    const bool rebuilt = buildStencil();
    lap("Weights");

    report(rebuilt);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cellCellStencils::octreeInverseDistance::octreeInverseDistance
(
    const fvMesh& mesh,
    const dictionary& dict,
    const bool doUpdate
)
:
    inverseDistance(mesh, dict, false),
    settings_(dict_, typeName, countZones(zoneID())),
    zoneParts_(),
    zoneSearch_(),
    prevDonor_(),
    cacheNCells_(-1),
    fullReason_("first update"),
    bins_(),
    timers_(stepTimers::New(mesh.time())),
    lapStart_(),
    procBb_(),
    prevRemote_(),
    localVoxels_(),
    patchFilledSmallVec_(),
    patchFilledPoints_(),
    patchVoxels_(),
    voxelExchange_(),
    cellRadius_(),
    followPoints0_(),
    followMin0_(Zero),
    searchBoxShift_(Zero),
    zoneResidual_(),
    nearlyRigidSaid_(),
    donorGlobal_(),
    stencilGlobal_(),
    ws_(),
    flood_(mesh),
    floodCounts_(),
    nQueriesSent_(0),
    nQueriesRetried_(0),
    nQueriesAnswered_(0),
    nHoleTested_(0),
    nDonorSearched_(0),
    nStencilBuilt_(0),
    nStencilReused_(0)
{
    if (doUpdate)
    {
        update();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::cellCellStencils::octreeInverseDistance::update()
{
    stepTimers::scope timer(timers_, stencilPart);

    if (settings_.search() == octreeStencilSettings::searchType::stock)
    {
        return inverseDistance::update();
    }

    updateCached();

    return true;
}


// ************************************************************************* //
