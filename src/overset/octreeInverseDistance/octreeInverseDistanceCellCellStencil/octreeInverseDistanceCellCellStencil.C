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
#include "mapDistribute.H"
#include "stepTimers.H"
#include "Time.H"
#include "cellSet.H"
#include "OStringStream.H"

#include <cstdio>
#include <string>

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

const Foam::Enum
<
    Foam::cellCellStencils::octreeInverseDistance::holeCuttingType
>
Foam::cellCellStencils::octreeInverseDistance::holeCuttingTypeNames
({
    { holeCuttingType::incremental, "incremental" },
    { holeCuttingType::full, "full" },
});

const Foam::word
Foam::cellCellStencils::octreeInverseDistance::stencilPart("oversetStencil");

const Foam::scalar
Foam::cellCellStencils::octreeInverseDistance::residualMargin(4);

const Foam::scalar
Foam::cellCellStencils::octreeInverseDistance::radiusTolerance(1e-6);

const Foam::scalar
Foam::cellCellStencils::octreeInverseDistance::candidateRoundOff(1e-9);

const Foam::word
Foam::cellCellStencils::octreeInverseDistance::orphanSetName
(
    "octreeInverseDistanceOrphans"
);

const Foam::word
Foam::cellCellStencils::octreeInverseDistance::emptyStencilField
(
    "octreeInverseDistanceCellTypes"
);


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- FNV-1a over the bytes of n values
template<class T>
void hashBytes(uint64_t& h, const T* values, const std::size_t n)
{
    const unsigned char* bytes = reinterpret_cast<const unsigned char*>(values);
    for (std::size_t i = 0; i < n*sizeof(T); ++i)
    {
        h ^= bytes[i];
        h *= 1099511628211ull;
    }
}

//- A checksum as 16 hex digits
std::string checksumHex(const uint64_t h)
{
    char buf[24];
    std::snprintf
    (
        buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(h)
    );
    return buf;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

uint64_t Foam::cellCellStencils::octreeInverseDistance::stencilChecksum
(
    const globalIndex& globalCells
) const
{
    uint64_t sum = 0;
    for (const label celli : interpolationCells_)
    {
        uint64_t h = 14695981039346656037ull;
        const label globalCelli = globalCells.toGlobal(celli);
        hashBytes(h, &globalCelli, 1);
        const labelList& stencil = stencilGlobal_[celli];
        hashBytes(h, stencil.cdata(), stencil.size());
        const scalarList& weights = cellInterpolationWeights_[celli];
        hashBytes(h, weights.cdata(), weights.size());
        hashBytes(h, &cellInterpolationWeight_[celli], 1);
        sum += h;
    }
    reduce(sum, sumOp<uint64_t>());
    return sum;
}


void Foam::cellCellStencils::octreeInverseDistance::readSettings()
{
    const word searchName
    (
        dict_.getOrDefault<word>("search", searchTypeNames[searchType::cached])
    );
    if (!searchTypeNames.found(searchName))
    {
        FatalIOErrorInFunction(dict_)
            << "search " << searchName << " unknown: must be one of "
            << searchTypeNames.sortedToc() << exit(FatalIOError);
    }
    search_ = searchTypeNames[searchName];

    const word holeCuttingName
    (
        dict_.getOrDefault<word>
        (
            "holeCutting",
            holeCuttingTypeNames[holeCuttingType::incremental]
        )
    );
    if (!holeCuttingTypeNames.found(holeCuttingName))
    {
        FatalIOErrorInFunction(dict_)
            << "holeCutting " << holeCuttingName << " unknown: must be one of "
            << holeCuttingTypeNames.sortedToc() << exit(FatalIOError);
    }
    holeCutting_ = holeCuttingTypeNames[holeCuttingName];

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

    noHoleCut_.clear();
    if (dict_.readIfPresent("noHoleCut", noHoleCut_))
    {
        const label nZones = countZones(this->zoneID());
        for (const labelPair& p : noHoleCut_)
        {
            if
            (
                p.first() < 0 || p.first() >= nZones
             || p.second() < 0 || p.second() >= nZones
             || p.first() == p.second()
            )
            {
                FatalIOErrorInFunction(dict_)
                    << "noHoleCut entry " << p << ": a pair (zone cutter) of"
                    << " two different zones, each in [0, " << nZones - 1
                    << "] (the zoneID values)" << exit(FatalIOError);
            }
        }
        if (noHoleCut_.size() && search_ != searchType::cached)
        {
            FatalIOErrorInFunction(dict_)
                << "noHoleCut " << noHoleCut_ << " needs search "
                << searchTypeNames[searchType::cached]
                << " (search " << searchTypeNames[search_]
                << " is the stock update, which cuts every pair)"
                << exit(FatalIOError);
        }
    }
}


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


bool Foam::cellCellStencils::octreeInverseDistance::cuts
(
    const label cutter,
    const label zone
) const
{
    for (const labelPair& p : noHoleCut_)
    {
        if (p.first() == zone && p.second() == cutter)
        {
            return false;
        }
    }
    return true;
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
    zoneSearch_.set(zonei, new zoneDonorSearch(subMesh, maxWalk_));

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

    // Voxel maps: refilled at the next update
    localVoxels_ = List<patchVoxelMap>(nZones);
    patchFilledSmallVec_.setSize(nZones, Zero);
    patchFilledPoints_.setSize(nZones);
    patchVoxels_.setSize(nZones);
    remoteVoxels_ = List<patchVoxelMap>(nZones);

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


bool Foam::cellCellStencils::octreeInverseDistance::voxelsCurrent
(
    const label zonei,
    const boundBox& bb,
    const labelVector& nDivs
) const
{
    const patchVoxelMap& map = localVoxels_[zonei];
    if
    (
        !map.allocated()
     || map.nDivs() != nDivs
     || map.bb() != bb
     || patchFilledSmallVec_[zonei] != smallVec_
    )
    {
        return false;
    }

    const labelList& pointMap = zoneParts_[zonei].pointMap();
    const pointField& points = mesh_.points();
    const pointField& filledPoints = patchFilledPoints_[zonei];

    if (filledPoints.size() != pointMap.size())
    {
        return false;
    }
    forAll(pointMap, i)
    {
        if (points[pointMap[i]] != filledPoints[i])
        {
            return false;
        }
    }
    return true;
}


void Foam::cellCellStencils::octreeInverseDistance::markZoneBoundaries
(
    const label zonei,
    const bool fillVoxels,
    labelList& patchCellTypes
)
{
    // Voxels of the zone's boundary faces at the current pose: the zones
    // share no faces, so the zone's sub-mesh boundary is the mesh boundary
    // restricted to the zone (the sub-mesh's exposed-face patch is empty)

    const labelList& zoneID = this->zoneID();
    const fvBoundaryMesh& pbm = mesh_.boundary();
    const pointField& points = mesh_.points();
    patchVoxelMap& map = localVoxels_[zonei];

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

            const labelList& fc = fvp.faceCells();
            const polyPatch& pp = fvp.patch();

            forAll(pp, i)
            {
                if (zoneID[fc[i]] != zonei)
                {
                    continue;
                }
                patchCellTypes[fc[i]] =
                    oversetPass ? patchCellType::OVERSET : patchCellType::PATCH;

                if (!fillVoxels)
                {
                    continue;
                }

                boundBox faceBb(points, pp[i], false);
                faceBb.min() -= smallVec_;
                faceBb.max() += smallVec_;

                if (oversetPass)
                {
                    map.fillOversetFace(faceBb);
                }
                else
                {
                    map.fillPatchFace(faceBb);
                }
            }
        }
    }

    if (fillVoxels)
    {
        // What the map was filled with
        patchFilledSmallVec_[zonei] = smallVec_;

        const labelList& pointMap = zoneParts_[zonei].pointMap();
        pointField& filledPoints = patchFilledPoints_[zonei];
        filledPoints.setSize(pointMap.size());
        forAll(pointMap, i)
        {
            filledPoints[i] = points[pointMap[i]];
        }
    }
}


void Foam::cellCellStencils::octreeInverseDistance::markHoles
(
    const patchVoxelMap& src,
    const label tgtI,
    const boundBox& tgtBb,
    const bool incremental,
    labelList& allCellTypes
)
{
    if (src.noPatch() || !src.bb().overlaps(tgtBb))
    {
        return;
    }

    const labelVector maxIndex(src.nDivs() - labelVector::one);
    const labelList& cellMap = zoneParts_[tgtI].cellMap();
    const scalarField& radius = cellRadius_[tgtI];
    const pointField& cc = mesh_.cellCentres();

    // Deviation from rigid motion (points and centre) and round-off
    const scalar margin = residualMargin*zoneResidual_[tgtI];

    // The cells to test (zone cell indices): those the PATCH blocks can
    // reach, or all
    const labelList tested
    (
        incremental
      ? holeCandidates(tgtI, src)
      : identity(cellMap.size())
    );
    nHoleTested_ += tested.size();

    for (const label i : tested)
    {
        const label celli = cellMap[i];

        // Voxel range of a box holding the cell's bounding box
        const vector r
        (
            vector::uniform((1 + radiusTolerance)*radius[i] + margin)
          + smallVec_
        );
        const labelVector lo(max(labelVector::zero, src.voxel(cc[celli] - r)));
        const labelVector hi(min(maxIndex, src.voxel(cc[celli] + r)));

        // Any block holding a PATCH voxel?
        if (!src.meetsPatchRange(lo, hi) || !src.anyPatchBlock(lo, hi))
        {
            continue;
        }

        // The stock test
        treeBoundBox cBb(cellBb(mesh_, celli));
        cBb.min() -= smallVec_;
        cBb.max() += smallVec_;

        if (src.overlapsPatch(cBb))
        {
            allCellTypes[celli] = HOLE;
        }
    }
}


Foam::labelList
Foam::cellCellStencils::octreeInverseDistance::holeCandidates
(
    const label tgtI,
    const patchVoxelMap& src
) const
{
    // The hole test's margins: the rigid-fit residual (cell centre and
    // radius) and the tolerance; sqrt(3) turns the boxes of the test into
    // balls, which rotate into the zone's frame unchanged
    const scalar m = residualMargin*zoneResidual_[tgtI];
    const scalar grow =
        Foam::sqrt(3.0)*(m + cmptMax(cmptMag(smallVec_))) + m
      + candidateRoundOff*mag(src.bb().span());

    return bins_[tgtI].holeCandidates(src, zoneSearch_[tgtI], grow);
}


void Foam::cellCellStencils::octreeInverseDistance::findDonors
(
    const labelUList& cells,
    const globalIndex& globalCells,
    const labelList& allCellTypes,
    labelListList& allStencil,
    labelList& allDonor
)
{
    const labelList& zoneID = this->zoneID();
    const pointField& cc = mesh_.cellCentres();
    const labelListList& cellCells = mesh_.cellCells();

    nDonorSearched_ += cells.size();

    forAll(zoneSearch_, srcI)
    {
        const zoneDonorSearch& search = zoneSearch_[srcI];
        const labelList& srcCellMap = zoneParts_[srcI].cellMap();
        labelList& prev = prevDonor_[srcI];

        for (const label celli : cells)
        {
            const label tgtI = zoneID[celli];
            if (tgtI == srcI)
            {
                continue;
            }

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
                allStencil[celli][0] =
                    globalCells.toGlobal(srcCellMap[srcCelli]);
                allDonor[celli] = srcI;
            }
        }
    }
}


Foam::labelList Foam::cellCellStencils::octreeInverseDistance::findOrphans
(
    const labelUList& cellTypes,
    const bitSet& isOversetPatchCell,
    const labelListList& stencil
)
{
    DynamicList<label> orphans;
    forAll(cellTypes, celli)
    {
        if
        (
            cellTypes[celli] != HOLE
         && isOversetPatchCell[celli]
         && stencil[celli].empty()
        )
        {
            orphans.append(celli);
        }
    }
    return labelList(std::move(orphans));
}


void Foam::cellCellStencils::octreeInverseDistance::reportOrphans
(
    const labelList& orphans
) const
{
    const label nOrphans = returnReduce(orphans.size(), sumOp<label>());

    if (nOrphans)
    {
        // A few locations from every rank
        const pointField& cc = mesh_.cellCentres();
        const labelList& zoneID = this->zoneID();
        const label nShow = min(orphans.size(), label(5));

        List<labelList> shownCells(Pstream::nProcs());
        List<labelList> shownZones(Pstream::nProcs());
        List<pointField> shownCentres(Pstream::nProcs());
        const label proci = Pstream::myProcNo();
        shownCells[proci] = SubList<label>(orphans, nShow);
        shownZones[proci] = labelUIndList(zoneID, shownCells[proci]);
        shownCentres[proci] = pointField(cc, shownCells[proci]);
        Pstream::gatherList(shownCells);
        Pstream::gatherList(shownZones);
        Pstream::gatherList(shownCentres);

        Info<< type() << " : " << nOrphans << " orphan cells (need a"
            << " donor, found none; now holes) at time "
            << mesh_.time().timeName() << "; at most 5 per rank:" << nl;
        forAll(shownCells, proci)
        {
            forAll(shownCells[proci], i)
            {
                Info<< "    cell " << shownCells[proci][i];
                if (Pstream::parRun())
                {
                    Info<< " of processor" << proci;
                }
                Info<< " zone " << shownZones[proci][i]
                    << " at " << shownCentres[proci][i] << nl;
            }
        }
        Info<< "    cellSet " << orphanSetName << endl;
    }

    if (nOrphans || mesh_.time().writeTime())
    {
        cellSet set
        (
            mesh_,
            orphanSetName,
            labelHashSet(orphans),
            IOobject::NO_WRITE
        );
        // In the time folder (the default, facesInstance, is constant for
        // a moving mesh without topology changes)
        set.instance() = mesh_.time().timeName();
        set.write();
    }
}


bool Foam::cellCellStencils::octreeInverseDistance::createStencilOnePass
(
    const globalIndex& globalCells
)
{
    const label nCells = mesh_.nCells();
    const labelList& acceptors = interpolationCells_;

    // The donors in compact numbering (local cells first, then the remote
    // ones), and the map that brings a donor's data to its acceptors
    labelList slots(donorGlobal_);
    List<Map<label>> compactMap;
    const mapDistribute donorMap(globalCells, slots, compactMap);

    // The local cells that are donors, here or on another rank
    bitSet isDonor(nCells);
    for (const label slot : slots)
    {
        if (slot < nCells)
        {
            isDonor.set(slot);
        }
    }
    forAll(donorMap.subMap(), proci)
    {
        if (proci != Pstream::myProcNo())
        {
            isDonor.set(donorMap.subMap()[proci]);
        }
    }

    // The donors and their valid face neighbours, as the stock createStencil
    boolList isValidDonor(nCells, true);
    forAll(cellTypes_, celli)
    {
        if (cellTypes_[celli] == HOLE)
        {
            isValidDonor[celli] = false;
        }
    }

    labelListList donorCellCells(nCells);
    pointListList donorCellCentres(nCells);
    globalCellCells
    (
        globalCells,
        mesh_,
        isValidDonor,
        isDonor.toc(),
        donorCellCells,
        donorCellCentres
    );
    donorMap.distribute(donorCellCells);
    donorMap.distribute(donorCellCentres);

    // Addressing unchanged (on every rank)?  Same interpolated cells with
    // the same stencils
    bool same =
        cellInterpolationMap_.valid()
     && stencilGlobal_.size() == nCells
     && cellStencil_.size() == nCells
     && cellInterpolationWeights_.size() == nCells;

    if (same)
    {
        label nStencil = 0;
        forAll(stencilGlobal_, celli)
        {
            if (stencilGlobal_[celli].size())
            {
                ++nStencil;
            }
        }
        same = (nStencil == acceptors.size());
    }
    for (label i = 0; same && i < acceptors.size(); ++i)
    {
        same = (stencilGlobal_[acceptors[i]] == donorCellCells[slots[i]]);
    }
    reduce(same, andOp<bool>());

    // Weights from the acceptor's centre (stock stencilWeights)
    const pointField& cc = mesh_.cellCentres();

    // Acceptors left without a stencil: the donor became a hole after the
    // donor search (flood fill or fringe walk) and so did all its
    // neighbours.  The stock stencil keeps them interpolated from nothing
    // (the momentum matrix then has a zero diagonal there); same here,
    // with a warning that says where
    {
        DynamicList<label> empty;
        forAll(acceptors, i)
        {
            if (donorCellCells[slots[i]].empty())
            {
                empty.append(i);
            }
        }
        const label nEmpty = returnReduce(empty.size(), sumOp<label>());
        if (nEmpty)
        {
            OStringStream where;
            for (const label i : empty)
            {
                const label celli = acceptors[i];
                where
                    << nl << "    cell " << celli << " zone "
                    << zoneID()[celli] << " at " << cc[celli];
                if (slots[i] < nCells)
                {
                    where
                        << ": donor " << slots[i] << " zone "
                        << zoneID()[slots[i]] << " at " << cc[slots[i]];
                }
            }
            WarningInFunction
                << nEmpty << " interpolated cells have an empty stencil"
                << " (their donor and its neighbours are holes) at time "
                << mesh_.time().timeName() << "; on this rank:"
                << where.str().c_str() << nl
                << "    cell types written as field " << emptyStencilField
                << endl;

            tmp<volScalarField> types
            (
                createField(mesh_, emptyStencilField, cellTypes_)
            );
            types.ref().instance() = mesh_.time().timeName();
            types().write();
        }
    }

    if (same)
    {
        forAll(acceptors, i)
        {
            stencilWeights
            (
                cc[acceptors[i]],
                donorCellCentres[slots[i]],
                cellInterpolationWeights_[acceptors[i]]
            );
        }
        ++nStencilReused_;
        return false;
    }

    stencilGlobal_.setSize(nCells);
    cellStencil_.setSize(nCells);
    cellInterpolationWeights_.setSize(nCells);
    forAll(stencilGlobal_, celli)
    {
        stencilGlobal_[celli].clear();
        cellStencil_[celli].clear();
        cellInterpolationWeights_[celli].clear();
    }
    forAll(acceptors, i)
    {
        const label celli = acceptors[i];
        stencilGlobal_[celli] = donorCellCells[slots[i]];
        cellStencil_[celli] = stencilGlobal_[celli];
        stencilWeights
        (
            cc[celli],
            donorCellCentres[slots[i]],
            cellInterpolationWeights_[celli]
        );
    }

    // Compact the stencil (global -> compact numbering)
    compactMap.clear();
    cellInterpolationMap_.reset
    (
        new mapDistribute(globalCells, cellStencil_, compactMap)
    );
    ++nStencilBuilt_;
    return true;
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
        timers_.add
        (
            word(stencilPart + part),
            stepTimers::seconds(lapStart, now)
        );
        lapStart = now;
    };

    const bool parallel = Pstream::parRun();
    const label nZones = zoneSearch_.size();
    smallVec_ = mesh_.bounds().span()*tolerance_;
    const pointField& points = mesh_.points();

    // 1. Rigid transform of each zone (the same on every rank); rebuild a
    //    deforming zone; the whole zone's current box
    List<treeBoundBoxList> zoneBb(nZones, treeBoundBoxList(1));
    for (label zonei = 0; zonei < nZones; ++zonei)
    {
        const labelList& pointMap = zoneParts_[zonei].pointMap();
        const scalar residual =
            zoneSearch_[zonei].fitTransform(points, pointMap);
        zoneResidual_[zonei] = residual;
        const scalar size = zoneSearch_[zonei].size();

        if (residual > rigidTolerance_*size)
        {
            WarningInFunction
                << "zone " << zonei << " is not rigid: point residual "
                << residual << " > rigidTolerance*size "
                << rigidTolerance_*size << "; rebuilding its search cache"
                << endl;
            buildZone(zonei, zoneID);
            fullReason_ = "zone " + Foam::name(zonei) + " rebuilt";
        }

        const boundBox bb(points, zoneParts_[zonei].pointMap(), true);
        if (!bb.empty())
        {
            zoneBb[zonei][0] = treeBoundBox(bb);
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
    for (label zonei = 0; zonei < nZones; ++zonei)
    {
        const labelVector& d = patchDivisions[zonei];
        const boundBox& bb = patchBb[zonei][0];

        // Refill only a zone that moved (or whose map box changed)
        const bool fillVoxels =
            returnReduce(!voxelsCurrent(zonei, bb, d), orOp<bool>());
        if (fillVoxels)
        {
            localVoxels_[zonei].reset(bb, d);
            if (debug && !localVoxels_[zonei].allOther())
            {
                FatalErrorInFunction
                    << "voxel map of zone " << zonei << " not reset"
                    << abort(FatalError);
            }
        }
        markZoneBoundaries(zonei, fillVoxels, allPatchTypes);
        if (fillVoxels && parallel)
        {
            patchVoxels_[zonei] = localVoxels_[zonei].patchVoxels();
        }
    }
    nVoxelsSent_ = 0;
    if (parallel)
    {
        exchangePatchVoxels(patchBb, patchDivisions);
    }

    lap("Voxels");

    // 3. Holes and donors.  Incremental: the hole test only for the cells
    //    the PATCH voxels can reach, donors only for the cells whose donors
    //    matter; full: every cell (the first update after the cache was
    //    built, or holeCutting full)
    const bool incremental =
        holeCutting_ == holeCuttingType::incremental && fullReason_.empty();
    const word mode
    (
        incremental ? word("incremental")
      : fullReason_.size() ? word("full (" + fullReason_ + ")")
      : word("full (holeCutting full)")
    );
    fullReason_.clear();

    labelList allCellTypes(mesh_.nCells(), CALCULATED);
    labelListList allStencil(mesh_.nCells());
    labelList allDonorID(mesh_.nCells(), -1);
    const globalIndex globalCells(mesh_.nCells());

    nHoleTested_ = 0;
    for (label srcI = 0; srcI < nZones - 1; ++srcI)
    {
        for (label tgtI = srcI + 1; tgtI < nZones; ++tgtI)
        {
            // This rank's patch voxels, then the other ranks'
            for (const label s : {srcI, tgtI})
            {
                const label t = (s == srcI ? tgtI : srcI);
                if (!cuts(s, t))
                {
                    continue;
                }
                markHoles
                (
                    localVoxels_[s], t, patchBb[t][0], incremental,
                    allCellTypes
                );
                if (parallel)
                {
                    markHoles
                    (
                        remoteVoxels_[s], t, patchBb[t][0], incremental,
                        allCellTypes
                    );
                }
            }
        }
    }

    lap("Holes");

    for (label zonei = 0; zonei < nZones; ++zonei)
    {
        zoneSearch_[zonei].resetCounters();
    }

    bitSet isOversetPatchCell(mesh_.nCells());
    forAll(allPatchTypes, celli)
    {
        if (allPatchTypes[celli] == patchCellType::OVERSET)
        {
            isOversetPatchCell.set(celli);
        }
    }

    // Donors (full: every cell on this rank) for the cells whose donors
    // matter, on this rank (incremental) and the others (parallel); the
    // donors must not be holes of the hole cutting
    const labelList holeTypes(allCellTypes);
    bitSet queried(mesh_.nCells());
    nQueriesSent_ = 0;
    nDonorSearched_ = 0;
    if (!incremental)
    {
        findDonors
        (
            identity(mesh_.nCells()), globalCells, allCellTypes, allStencil,
            allDonorID
        );
    }
    if (incremental || parallel)
    {
        searchDonors
        (
            donorCandidates(allCellTypes, isOversetPatchCell),
            incremental,
            globalCells,
            holeTypes,
            allStencil,
            allDonorID,
            queried
        );
    }

    lap("Donors");

    // 4. Cell types from the patch types and the donors, as the stock
    //    stencil: an overset-patch cell is interpolated if it has a donor,
    //    else a hole (an orphan); so is a cell that was a hole and is
    //    calculated now
    const labelList orphans
    (
        findOrphans(allCellTypes, isOversetPatchCell, allStencil)
    );

    forAll(allCellTypes, celli)
    {
        label& type = allCellTypes[celli];

        if (needsDonor(type, cellTypes_[celli], isOversetPatchCell[celli]))
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

    const labelList floodTypes(allCellTypes);
    scalarField allWeight(mesh_.nCells(), Zero);
    walkFrontResolved
    (
        !incremental,
        globalCells,
        holeTypes,
        floodTypes,
        allCellTypes,
        allStencil,
        allDonorID,
        allWeight,
        queried
    );

    lap("Flood");

    // 5. The inverse-distance stencil around each donor (the stock
    //    createStencil's result, one pass, addressing kept if unchanged)
    cellTypes_.transfer(allCellTypes);

    DynamicList<label> interpolated(mesh_.nCells()/10);
    forAll(cellTypes_, celli)
    {
        if (cellTypes_[celli] == INTERPOLATED)
        {
            if (allStencil[celli].size() != 1)
            {
                FatalErrorInFunction
                    << "interpolated cell " << celli << " has "
                    << allStencil[celli].size() << " donors instead of 1"
                    << abort(FatalError);
            }
            interpolated.append(celli);
        }
    }
    interpolationCells_.transfer(interpolated);
    donorGlobal_.setSize(interpolationCells_.size());
    forAll(interpolationCells_, i)
    {
        donorGlobal_[i] = allStencil[interpolationCells_[i]][0];
    }

    cellInterpolationWeight_.transfer(allWeight);
    dynamicOversetFvMesh::correctBoundaryConditions
    <
        volScalarField,
        oversetFvPatchField<scalar>
    >(cellInterpolationWeight_.boundaryFieldRef(), false);

    const bool rebuilt = createStencilOnePass(globalCells);

    lap("Weights");

    // Log
    {
        const labelList nCells(count(3, cellTypes_));
        const uint64_t checksum = stencilChecksum(globalCells);
        Info<< type() << " : calculated " << nCells[CALCULATED]
            << " interpolated " << nCells[INTERPOLATED]
            << " hole " << nCells[HOLE]
            << " orphan " << returnReduce(orphans.size(), sumOp<label>())
            << " stencil " << (rebuilt ? "rebuilt" : "reused")
            << " (rebuilt " << nStencilBuilt_
            << " reused " << nStencilReused_ << ")" << nl << incrIndent
            << indent << "holes " << mode << ": hole test "
            << returnReduce(nHoleTested_, sumOp<label>())
            << " cells, donor search "
            << returnReduce(nDonorSearched_, sumOp<label>())
            << " cells; stencil checksum " << word(checksumHex(checksum))
            << nl;
        forAll(zoneSearch_, zonei)
        {
            const zoneDonorSearch& s = zoneSearch_[zonei];
            Info<< indent << "donor zone " << zonei
                << " : rigid fit residual " << zoneResidual_[zonei]
                << " walk " << returnReduce(s.nWalk(), sumOp<label>())
                << " octree " << returnReduce(s.nOctree(), sumOp<label>())
                << " outside " << returnReduce(s.nOutside(), sumOp<label>())
                << nl;
        }
        if (parallel)
        {
            Info<< indent << "sent: patch voxels "
                << returnReduce(nVoxelsSent_, sumOp<label>())
                << " donor queries "
                << returnReduce(nQueriesSent_, sumOp<label>()) << nl;
        }
        Info<< decrIndent << endl;
    }

    reportOrphans(orphans);
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
    holeCutting_(holeCuttingType::incremental),
    maxWalk_(16),
    rigidTolerance_(1e-6),
    layerRelax_(1),
    tolerance_(1e-10),
    useSearchBox_(false),
    searchBox_(),
    useDivisions_(false),
    divisions_(Zero),
    noHoleCut_(),
    zoneParts_(),
    zoneSearch_(),
    prevDonor_(),
    cacheNCells_(-1),
    fullReason_("first update"),
    bins_(),
    timers_(stepTimers::New(mesh.time())),
    procBb_(),
    prevRemote_(),
    localVoxels_(),
    patchFilledSmallVec_(),
    patchFilledPoints_(),
    patchVoxels_(),
    remoteVoxels_(),
    nVoxelsSent_(0),
    nQueriesSent_(0),
    nHoleTested_(0),
    nDonorSearched_(0),
    cellRadius_(),
    zoneResidual_(),
    donorGlobal_(),
    stencilGlobal_(),
    nStencilBuilt_(0),
    nStencilReused_(0)
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

    updateCached();

    return true;
}


// ************************************************************************* //
