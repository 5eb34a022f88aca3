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


Description
    octreeInverseDistance: the patch voxel maps and the hole cutting.  The
    hole test only for the cells the PATCH voxels can reach (bins of each
    zone's cells in the zone's own frame, Foam::cellBins).

\*---------------------------------------------------------------------------*/

#include "octreeInverseDistanceCellCellStencil.H"
#include "oversetFvPatch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::cellCellStencils::octreeInverseDistance::cuts
(
    const label cutter,
    const label zone
) const
{
    for (const labelPair& p : settings_.noHoleCut())
    {
        if (p.first() == zone && p.second() == cutter)
        {
            return false;
        }
    }
    return true;
}


bool Foam::cellCellStencils::octreeInverseDistance::voxelsCurrent
(
    const label zonei,
    const boundBox& bb,
    const labelVector& nDivs
)
{
    patchVoxelMap& map = localVoxels_[zonei];
    const bool follow = settings_.searchBoxFollows() >= 0;
    if
    (
        !map.allocated()
     || map.nDivs() != nDivs
     || (!follow && map.bb() != bb)
     || mag(patchFilledSmallVec_[zonei] - smallVec_)
      > (follow ? 1e-9*mag(smallVec_) : 0)
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

    // A box that follows a zone: the points and the box translated alike
    // since the fill (within the tolerance) leave the voxels in the box
    // as they were
    const vector shift(bb.min() - map.fillBb().min());
    const vector tol(follow ? cmptMag(smallVec_) : vector::zero);
    const auto beyond = [&tol](const vector& d)
    {
        return
            mag(d.x()) > tol.x() || mag(d.y()) > tol.y()
         || mag(d.z()) > tol.z();
    };
    if (beyond(bb.span() - map.fillBb().span()))
    {
        return false;
    }
    forAll(pointMap, i)
    {
        if (beyond(points[pointMap[i]] - filledPoints[i] - shift))
        {
            return false;
        }
    }
    map.moveBox(bb);
    return true;
}


Foam::labelVector
Foam::cellCellStencils::octreeInverseDistance::voxelDivisions() const
{
    if (settings_.useDivisions())
    {
        return settings_.divisions();
    }

    // As the stock stencil, about one voxel a cell, but of the whole mesh:
    // the grid must be the same on every rank (the PATCH voxels travel as
    // indices), and it is then the serial run's grid.  (The stock stencil
    // takes each rank's own cells and box: its holes in parallel depend on
    // the decomposition; see readSearchBox.)
    const label nD = mesh_.nGeometricD();
    const scalar n = scalar(returnReduce(mesh_.nCells(), sumOp<label>()));
    const label nDivs =
        nD == 1 ? label(n) : nD == 2 ? label(Foam::sqrt(n))
      : label(Foam::cbrt(n));
    const labelVector& dirs = mesh_.geometricD();
    labelVector divs;
    for (direction d = 0; d < 3; ++d)
    {
        divs[d] = (dirs[d] == -1 ? 1 : nDivs);
    }
    return divs;
}


Foam::List<Foam::boundBox>
Foam::cellCellStencils::octreeInverseDistance::markZoneBoundaries
(
    const label zonei,
    const bool fillVoxels
)
{
    DynamicList<boundBox> dropped;
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
                ws_.patchTypes[fc[i]] =
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
                else if (!map.fillPatchFace(faceBb))
                {
                    dropped.append(faceBb);
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
    return List<boundBox>(std::move(dropped));
}


void Foam::cellCellStencils::octreeInverseDistance::checkSearchBox
(
    const label zonei,
    const List<boundBox>& dropped
) const
{
    // The first dropped face that meets another zone's box (all ranks,
    // current pose), that zone; -1: none
    boundBox face;
    label met = -1;
    forAll(zoneSearch_, zonej)
    {
        if (zonej == zonei || !cuts(zonei, zonej))
        {
            continue;
        }
        treeBoundBox bb0(treeBoundBox::invertedBox);
        for (const treeBoundBox& procBb : procBb_[zonej])
        {
            if (!procBb.empty())
            {
                bb0.add(procBb);
            }
        }
        const treeBoundBox bb(zoneSearch_[zonej].toCurrent(bb0));
        for (const boundBox& faceBb : dropped)
        {
            if (met == -1 && bb.overlaps(faceBb))
            {
                face = faceBb;
                met = zonej;
            }
        }
    }

    if (returnReduce(met, maxOp<label>()) != -1)
    {
        FatalIOErrorInFunction(dict_)
            << "searchBox " << currentSearchBox()
            << " does not contain the"
            << " walls of zone " << zonei << " at time "
            << mesh_.time().timeName() << ": e.g. the wall face in "
            << face << " meets zone " << met << " and would cut no holes"
            << " there; searchBox must contain every zone's walls where"
            << " they meet another zone, at every pose (or leave searchBox"
            << " out: the zones' own boxes)" << exit(FatalIOError);
    }
}


void Foam::cellCellStencils::octreeInverseDistance::markHoles
(
    const patchVoxelMap& src,
    const label tgtI
)
{
    if (src.noPatch() || !src.bb().overlaps(ws_.patchBb[tgtI][0]))
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
        ws_.incremental
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
            ws_.cellTypes[celli] = HOLE;
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


void Foam::cellCellStencils::octreeInverseDistance::fillVoxels()
{
    const label nZones = zoneSearch_.size();
    const bool parallel = Pstream::parRun();

    ws_.patchBb = ws_.zoneBb;
    if (settings_.useSearchBox())
    {
        ws_.patchBb = treeBoundBoxList(1, currentSearchBox());
    }
    ws_.patchDivs = voxelDivisions();

    for (label zonei = 0; zonei < nZones; ++zonei)
    {
        const labelVector& d = ws_.patchDivs[zonei];
        const boundBox& bb = ws_.patchBb[zonei][0];

        // Refill only a zone that moved (or whose map box changed)
        const bool fill =
            returnReduce(!voxelsCurrent(zonei, bb, d), orOp<bool>());
        if (fill)
        {
            localVoxels_[zonei].reset(bb, d);
            if (debug && !localVoxels_[zonei].allOther())
            {
                FatalErrorInFunction
                    << "voxel map of zone " << zonei << " not reset"
                    << abort(FatalError);
            }
        }
        const List<boundBox> dropped(markZoneBoundaries(zonei, fill));
        if (fill && settings_.useSearchBox())
        {
            checkSearchBox(zonei, dropped);
        }
        if (fill && parallel)
        {
            patchVoxels_[zonei] = localVoxels_[zonei].patchVoxelBlocks();
        }
    }

    forAll(ws_.patchTypes, celli)
    {
        if (ws_.patchTypes[celli] == patchCellType::OVERSET)
        {
            ws_.isOversetPatchCell.set(celli);
        }
    }

    if (parallel)
    {
        voxelExchange_.exchange(localVoxels_, patchVoxels_, voxelTargets());
    }
}


void Foam::cellCellStencils::octreeInverseDistance::cutHoles()
{
    // Incremental: the hole test only for the cells the PATCH voxels can
    // reach; full: every cell (the first update after the cache was built,
    // or holeCutting full)
    ws_.incremental =
        settings_.holeCutting()
     == octreeStencilSettings::holeCuttingType::incremental
     && fullReason_.empty();
    ws_.mode =
        ws_.incremental ? word("incremental")
      : fullReason_.size() ? word("full (" + fullReason_ + ")")
      : word("full (holeCutting full)");
    fullReason_.clear();

    const label nZones = zoneSearch_.size();
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
                markHoles(localVoxels_[s], t);
                if (Pstream::parRun())
                {
                    markHoles(voxelExchange_.remote(s), t);
                }
            }
        }
    }
}



// ************************************************************************* //
