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

#include "holeFlood.H"
#include "cellCellStencil.H"
#include "oversetFvPatch.H"
#include "regionSplit.H"
#include "syncTools.H"
#include "mapDistribute.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{
    constexpr Foam::label hole = Foam::cellCellStencil::HOLE;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::boolList Foam::holeFlood::holeBoundaries
(
    const labelUList& cellTypes
) const
{
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();

    boolList blocked(mesh_.nFaces(), false);
    for (label facei = 0; facei < nInternal; ++facei)
    {
        blocked[facei] =
            (cellTypes[own[facei]] == hole) != (cellTypes[nei[facei]] == hole);
    }

    labelList nbrTypes;
    syncTools::swapBoundaryCellList(mesh_, cellTypes, nbrTypes);
    for (label facei = nInternal; facei < mesh_.nFaces(); ++facei)
    {
        blocked[facei] =
            (cellTypes[own[facei]] == hole)
         != (nbrTypes[facei - nInternal] == hole);
    }
    return blocked;
}


void Foam::holeFlood::localStatus
(
    const boolList& blocked,
    const labelUList& cellTypes
)
{
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();

    // Borders a hole: the non-hole side of an internal hole boundary, the
    // owner side of a boundary one (as the stock)
    forAll(blocked, facei)
    {
        if (!blocked[facei])
        {
            continue;
        }
        const label owni = own[facei];
        if (facei >= nInternal || cellTypes[owni] != hole)
        {
            status_[cellRegion_[owni]] =
                max(status_[cellRegion_[owni]], label(BORDERS));
        }
        if (facei < nInternal && cellTypes[nei[facei]] != hole)
        {
            const label r = cellRegion_[nei[facei]];
            status_[r] = max(status_[r], label(BORDERS));
        }
    }

    // Reached: a non-hole cell on a real patch
    for (const fvPatch& fvp : mesh_.boundary())
    {
        if (isA<oversetFvPatch>(fvp) || fvPatch::constraintType(fvp.type()))
        {
            continue;
        }
        for (const label celli : fvp.faceCells())
        {
            if (cellTypes[celli] != hole)
            {
                status_[cellRegion_[celli]] = REACHED;
            }
        }
    }
}


bool Foam::holeFlood::spread
(
    const boolList& blocked,
    const labelUList& acceptors,
    const labelListList& slots,
    const mapDistribute& map
)
{
    bool changed = false;
    labelList cellStatus(labelUIndList(status_, cellRegion_));

    // Across coupled faces that are not hole boundaries: one region
    labelList nbrStatus;
    syncTools::swapBoundaryCellList(mesh_, cellStatus, nbrStatus);
    const labelList& own = mesh_.faceOwner();
    const label nInternal = mesh_.nInternalFaces();
    forAll(nbrStatus, bFacei)
    {
        const label facei = nInternal + bFacei;
        label& s = status_[cellRegion_[own[facei]]];
        if (!blocked[facei] && nbrStatus[bFacei] > s)
        {
            s = nbrStatus[bFacei];
            changed = true;
        }
    }

    // From the donors of the overset-patch cells
    map.distribute(cellStatus);
    forAll(acceptors, i)
    {
        label& s = status_[cellRegion_[acceptors[i]]];
        if (s == REACHED)
        {
            continue;
        }
        for (const label slot : slots[i])
        {
            if (cellStatus[slot] == REACHED)
            {
                s = REACHED;
                changed = true;
                break;
            }
        }
    }

    return returnReduce(changed, orOp<bool>());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::holeFlood::holeFlood(const fvMesh& mesh)
:
    mesh_(mesh),
    cellRegion_(),
    status_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::holeFlood::counts Foam::holeFlood::apply
(
    const globalIndex& globalCells,
    const labelListList& stencil,
    labelList& cellTypes
)
{
    const boolList blocked(holeBoundaries(cellTypes));

    // This rank's regions, no global numbering
    regionSplit regions(mesh_, blocked, false);
    status_.setSize(regions.nLocalRegions());
    cellRegion_.transfer(regions);
    status_ = NONE;
    localStatus(blocked, cellTypes);

    // The overset-patch cells and their donors, in compact numbering
    DynamicList<label> acceptors;
    DynamicList<labelList> slots;
    for (const fvPatch& fvp : mesh_.boundary())
    {
        if (isA<oversetFvPatch>(fvp))
        {
            for (const label celli : fvp.faceCells())
            {
                acceptors.append(celli);
                slots.append(stencil[celli]);
            }
        }
    }
    labelListList compactSlots(std::move(slots));
    List<Map<label>> compactMap;
    const mapDistribute map(globalCells, compactSlots, compactMap);

    counts c;
    c.regions = status_.size();
    do
    {
        ++c.rounds;
    }
    while (spread(blocked, acceptors, compactSlots, map));

    forAll(cellTypes, celli)
    {
        if (status_[cellRegion_[celli]] == BORDERS && cellTypes[celli] != hole)
        {
            cellTypes[celli] = hole;
            ++c.holes;
        }
    }
    return c;
}


// ************************************************************************* //
