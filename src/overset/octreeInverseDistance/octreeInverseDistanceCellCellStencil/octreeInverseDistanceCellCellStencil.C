/*---------------------------------------------------------------------------*\
  flapFoam: free-flight simulation of flapping-wing drones on OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "octreeInverseDistanceCellCellStencil.H"
#include "addToRunTimeSelectionTable.H"
#include "dynamicOversetFvMesh.H"
#include "oversetFvPatch.H"
#include "oversetFvPatchField.H"
#include "globalIndex.H"
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

const Foam::Enum
<
    Foam::cellCellStencils::octreeInverseDistance::searchType
>
Foam::cellCellStencils::octreeInverseDistance::searchTypeNames
({
    { searchType::cached, "cached" },
    { searchType::stock, "stock" },
});

const Foam::word
Foam::cellCellStencils::octreeInverseDistance::stencilPart("oversetStencil");


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cellCellStencils::octreeInverseDistance::readSettings()
{
    search_ = searchTypeNames.getOrDefault("search", dict_, searchType::cached);

    maxWalk_ = dict_.getOrDefault<label>("maxWalk", 16);
    if (maxWalk_ < 0)
    {
        FatalIOErrorInFunction(dict_)
            << "maxWalk " << maxWalk_ << " out of range: must be >= 0"
            << exit(FatalIOError);
    }

    rigidTolerance_ = dict_.getOrDefault<scalar>("rigidTolerance", 1e-6);
    if (rigidTolerance_ <= 0 || rigidTolerance_ >= 1)
    {
        FatalIOErrorInFunction(dict_)
            << "rigidTolerance " << rigidTolerance_
            << " out of range: must be in (0, 1)" << exit(FatalIOError);
    }

    layerRelax_ = dict_.getOrDefault<scalar>("layerRelax", 1);
    if (layerRelax_ < 0 || layerRelax_ > 1)
    {
        FatalIOErrorInFunction(dict_)
            << "layerRelax " << layerRelax_
            << " out of range: must be in [0, 1]" << exit(FatalIOError);
    }

    tolerance_ = dict_.getOrDefault<scalar>("tolerance", 1e-10);
    if (tolerance_ <= 0 || tolerance_ >= 1)
    {
        FatalIOErrorInFunction(dict_)
            << "tolerance " << tolerance_
            << " out of range: must be in (0, 1)" << exit(FatalIOError);
    }

    useSearchBox_ = dict_.readIfPresent("searchBox", searchBox_);
    if (useSearchBox_ && searchBox_.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "searchBox " << searchBox_ << " is empty" << exit(FatalIOError);
    }

    useDivisions_ = dict_.readIfPresent("searchBoxDivisions", divisions_);
    if (useDivisions_ && cmptMin(divisions_) < 1)
    {
        FatalIOErrorInFunction(dict_)
            << "searchBoxDivisions " << divisions_
            << " out of range: every component must be >= 1"
            << exit(FatalIOError);
    }
}


bool Foam::cellCellStencils::octreeInverseDistance::cacheStale() const
{
    return
        zoneSearch_.empty()
     || cacheNCells_ != mesh_.nCells()
     || mesh_.topoChanging();
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
    zoneSearch_.set(zonei, new zoneDonorSearch(subMesh, maxWalk_));

    prevDonor_[zonei] = labelList(mesh_.nCells(), -1);
}


void Foam::cellCellStencils::octreeInverseDistance::buildCache
(
    const labelList& zoneID
)
{
    const label nZones = zoneID.size() ? max(zoneID) + 1 : 0;

    zoneSearch_.clear();
    zoneParts_.clear();
    zoneSearch_.setSize(nZones);
    zoneParts_.setSize(nZones);
    prevDonor_.setSize(nZones);

    for (label zonei = 0; zonei < nZones; ++zonei)
    {
        buildZone(zonei, zoneID);
    }
    cacheNCells_ = mesh_.nCells();

    Info<< type() << " : built the search cache of " << nZones
        << " zones in their own frames at time " << mesh_.time().timeName()
        << endl;
}


void Foam::cellCellStencils::octreeInverseDistance::markZoneBoundaries
(
    const label zonei,
    const labelList& zoneID,
    const boundBox& bb,
    const labelVector& nDivs,
    PackedList<2>& patchTypes,
    labelList& patchCellTypes
) const
{
    // Voxels of the zone's boundary faces at the current pose: the zones
    // share no faces, so the zone's sub-mesh boundary is the mesh boundary
    // restricted to the zone (the sub-mesh's exposed-face patch is empty)

    const fvBoundaryMesh& pbm = mesh_.boundary();
    const pointField& points = mesh_.points();

    patchTypes = patchCellType::OTHER;

    // Two passes, as the stock stencil: proper patches, then overset
    // patches on top
    for (const bool oversetPass : {false, true})
    {
        for (const fvPatch& fvp : pbm)
        {
            const bool isOverset = isA<oversetFvPatch>(fvp);
            const bool proper = !fvPatch::constraintType(fvp.type());

            if (oversetPass ? !isOverset : !proper)
            {
                continue;
            }

            const unsigned int val =
                oversetPass ? patchCellType::OVERSET : patchCellType::PATCH;

            const labelList& fc = fvp.faceCells();
            const polyPatch& pp = fvp.patch();

            forAll(pp, i)
            {
                if (zoneID[fc[i]] != zonei)
                {
                    continue;
                }
                patchCellTypes[fc[i]] = val;

                boundBox faceBb(points, pp[i], false);
                faceBb.min() -= smallVec_;
                faceBb.max() += smallVec_;

                if (bb.overlaps(faceBb))
                {
                    fill(patchTypes, bb, nDivs, faceBb, val);
                }
            }
        }
    }
}


void Foam::cellCellStencils::octreeInverseDistance::findDonors
(
    const globalIndex& globalCells,
    const labelList& allCellTypes,
    const label srcI,
    const label tgtI,
    labelListList& allStencil,
    labelList& allDonor
)
{
    const zoneDonorSearch& search = zoneSearch_[srcI];
    const labelList& srcCellMap = zoneParts_[srcI].cellMap();
    const labelList& tgtCellMap = zoneParts_[tgtI].cellMap();
    const pointField& cc = mesh_.cellCentres();
    const labelListList& cellCells = mesh_.cellCells();

    labelList& prev = prevDonor_[srcI];

    for (const label celli : tgtCellMap)
    {
        // Seed: the previous donor, else a face neighbour's donor
        label seed = prev[celli];
        if (seed < 0)
        {
            for (const label nbr : cellCells[celli])
            {
                if (prev[nbr] >= 0)
                {
                    seed = prev[nbr];
                    break;
                }
            }
        }

        const label srcCelli =
            search.findCell(search.toReference(cc[celli]), seed);
        prev[celli] = srcCelli;

        if
        (
            srcCelli != -1
         && allCellTypes[srcCellMap[srcCelli]] != HOLE
         && betterDonor(tgtI, allDonor[celli], srcI)
        )
        {
            allStencil[celli].setSize(1);
            allStencil[celli][0] = globalCells.toGlobal(srcCellMap[srcCelli]);
            allDonor[celli] = srcI;
        }
    }
}


void Foam::cellCellStencils::octreeInverseDistance::updateCached()
{
    const labelIOList& zoneID = this->zoneID();

    if (cacheStale())
    {
        buildCache(zoneID);
    }

    // Laps of the update as nested stepTimers parts (oversetStencil keeps
    // the rest: cache building, logging)
    stepTimers::clock::time_point lapStart = stepTimers::clock::now();
    auto lap = [&](const char* part)
    {
        const stepTimers::clock::time_point now = stepTimers::clock::now();
        timers_.add(word(stencilPart + part), stepTimers::seconds(lapStart, now));
        lapStart = now;
    };

    const label nZones = zoneSearch_.size();
    smallVec_ = mesh_.bounds().span()*tolerance_;
    const pointField& points = mesh_.points();

    // 1. Rigid transform of each zone; rebuild a deforming zone
    List<treeBoundBoxList> zoneBb(nZones, treeBoundBoxList(1));
    for (label zonei = 0; zonei < nZones; ++zonei)
    {
        const labelList& pointMap = zoneParts_[zonei].pointMap();
        const scalar residual =
            zoneSearch_[zonei].fitTransform(points, pointMap);
        const scalar size = mag(zoneSearch_[zonei].bb().span());

        if (residual > rigidTolerance_*size)
        {
            WarningInFunction
                << "zone " << zonei << " is not rigid: point residual "
                << residual << " > rigidTolerance*size "
                << rigidTolerance_*size << "; rebuilding its search cache"
                << endl;
            buildZone(zonei, zoneID);
        }

        if (pointMap.size())
        {
            zoneBb[zonei][0] = treeBoundBox(boundBox(points, pointMap, false));
            zoneBb[zonei][0].inflate(1e-6);
        }
        else
        {
            // As the stock stencil: a box outside the mesh
            const boundBox& allBb = mesh_.bounds();
            zoneBb[zonei][0] =
                treeBoundBox
                (
                    allBb.min() - 2*allBb.span(),
                    allBb.min() - allBb.span()
                );
            zoneBb[zonei][0].inflate(1e-6);
        }
    }

    lap("Transform");

    // 2. Patch voxel maps at the current pose
    List<treeBoundBoxList> patchBb(zoneBb);
    if (useSearchBox_)
    {
        patchBb = treeBoundBoxList(1, searchBox_);
    }

    List<labelVector> patchDivisions(nZones);
    {
        labelVector divs(divisions_);
        if (!useDivisions_)
        {
            const label nD = mesh_.nGeometricD();
            const scalar n = scalar(mesh_.nCells());
            const label nDivs =
                nD == 1 ? label(n) : nD == 2 ? label(Foam::sqrt(n))
              : label(Foam::cbrt(n));
            const labelVector& dirs = mesh_.geometricD();
            for (direction d = 0; d < 3; ++d)
            {
                divs[d] = (dirs[d] == -1 ? 1 : nDivs);
            }
        }
        patchDivisions = divs;
    }

    labelList allPatchTypes(mesh_.nCells(), patchCellType::OTHER);
    PtrList<PackedList<2>> patchParts(nZones);
    for (label zonei = 0; zonei < nZones; ++zonei)
    {
        const labelVector& d = patchDivisions[zonei];
        patchParts.set(zonei, new PackedList<2>(d.x()*d.y()*d.z()));
        markZoneBoundaries
        (
            zonei,
            zoneID,
            patchBb[zonei][0],
            d,
            patchParts[zonei],
            allPatchTypes
        );
    }

    // 3. Holes and donors, pairs of zones in the stock order
    labelList allCellTypes(mesh_.nCells(), CALCULATED);
    labelListList allStencil(mesh_.nCells());
    labelList allDonorID(mesh_.nCells(), -1);
    const globalIndex globalCells(mesh_.nCells());
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);

    for (label srcI = 0; srcI < nZones - 1; ++srcI)
    {
        for (label tgtI = srcI + 1; tgtI < nZones; ++tgtI)
        {
            markPatchesAsHoles
            (
                pBufs, zoneParts_, patchBb, patchDivisions, patchParts,
                srcI, tgtI, allCellTypes
            );
            markPatchesAsHoles
            (
                pBufs, zoneParts_, patchBb, patchDivisions, patchParts,
                tgtI, srcI, allCellTypes
            );
        }
    }

    lap("Holes");

    for (label zonei = 0; zonei < nZones; ++zonei)
    {
        zoneSearch_[zonei].resetCounters();
    }
    for (label srcI = 0; srcI < nZones - 1; ++srcI)
    {
        for (label tgtI = srcI + 1; tgtI < nZones; ++tgtI)
        {
            findDonors
            (
                globalCells, allCellTypes, tgtI, srcI, allStencil, allDonorID
            );
            findDonors
            (
                globalCells, allCellTypes, srcI, tgtI, allStencil, allDonorID
            );
        }
    }

    lap("Donors");

    // 4. Cell types from the patch types and the donors, as the stock
    //    stencil: an overset-patch cell is interpolated if it has a donor,
    //    else a hole; so is a cell that was a hole and is calculated now
    forAll(allCellTypes, celli)
    {
        label& type = allCellTypes[celli];

        const bool needsDonor =
            (type != HOLE && allPatchTypes[celli] == patchCellType::OVERSET)
         || (type == CALCULATED && cellTypes_[celli] == HOLE);

        if (needsDonor)
        {
            if (allStencil[celli].size())
            {
                type = INTERPOLATED;
            }
            else
            {
                type = HOLE;
                allStencil[celli].clear();
            }
        }
    }

    // Unreachable regions become holes; fringe layers around the holes
    findHoles(globalCells, mesh_, zoneID, allStencil, allCellTypes);

    scalarField allWeight(mesh_.nCells(), Zero);
    walkFront(layerRelax_, allStencil, allCellTypes, allWeight);

    lap("Flood");

    // 5. Donor-only stencil in compact form, then the inverse-distance
    //    stencil around each donor (stock createStencil)
    cellTypes_.transfer(allCellTypes);
    cellStencil_.setSize(mesh_.nCells());
    cellInterpolationWeights_.setSize(mesh_.nCells());

    DynamicList<label> interpolated(mesh_.nCells()/10);
    forAll(cellTypes_, celli)
    {
        if (cellTypes_[celli] == INTERPOLATED)
        {
            cellStencil_[celli].transfer(allStencil[celli]);
            cellInterpolationWeights_[celli] = scalarList(1, 1.0);
            interpolated.append(celli);
        }
        else
        {
            cellStencil_[celli].clear();
            cellInterpolationWeights_[celli].clear();
        }
    }
    interpolationCells_.transfer(interpolated);

    List<Map<label>> compactMap;
    cellInterpolationMap_.reset
    (
        new mapDistribute(globalCells, cellStencil_, compactMap)
    );
    cellInterpolationWeight_.transfer(allWeight);
    dynamicOversetFvMesh::correctBoundaryConditions
    <
        volScalarField,
        oversetFvPatchField<scalar>
    >(cellInterpolationWeight_.boundaryFieldRef(), false);

    createStencil(globalCells);

    lap("Weights");

    // Log
    {
        const labelList nCells(count(3, cellTypes_));
        Info<< type() << " : calculated " << nCells[CALCULATED]
            << " interpolated " << nCells[INTERPOLATED]
            << " hole " << nCells[HOLE] << nl << incrIndent;
        forAll(zoneSearch_, zonei)
        {
            const zoneDonorSearch& s = zoneSearch_[zonei];
            Info<< indent << "donor zone " << zonei
                << " : walk " << s.nWalk()
                << " octree " << s.nOctree()
                << " outside " << s.nOutside() << nl;
        }
        Info<< decrIndent << endl;
    }
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
    search_(searchType::cached),
    maxWalk_(16),
    rigidTolerance_(1e-6),
    layerRelax_(1),
    tolerance_(1e-10),
    useSearchBox_(false),
    searchBox_(),
    useDivisions_(false),
    divisions_(Zero),
    zoneParts_(),
    zoneSearch_(),
    prevDonor_(),
    cacheNCells_(-1),
    timers_(stepTimers::New(mesh.time())),
    parallelInfo_(false)
{
    readSettings();

    if (doUpdate)
    {
        update();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::cellCellStencils::octreeInverseDistance::update()
{
    stepTimers::scope timer(timers_, stencilPart);

    if (search_ == searchType::stock)
    {
        return inverseDistance::update();
    }

    if (Pstream::parRun())
    {
        if (!parallelInfo_)
        {
            Info<< type() << " : parallel run: the cached search is serial"
                << " only for now; using the stock inverseDistance update"
                << endl;
            parallelInfo_ = true;
        }
        return inverseDistance::update();
    }

    updateCached();

    return true;
}


// ************************************************************************* //
