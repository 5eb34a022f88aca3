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
    octreeInverseDistance: the donor search and the fringe.  Donors only for
    the cells whose donors matter (need one, border a hole, or are reached
    by the fringe walk), or for every cell (full update).

\*---------------------------------------------------------------------------*/

#include "octreeInverseDistanceCellCellStencil.H"
#include "syncTools.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cellCellStencils::octreeInverseDistance::findDonors
(
    const labelUList& cells
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
                currentDonor
                (
                    srcI,
                    cc[celli],
                    search.findCell(search.toReference(cc[celli]), seed)
                );
            prev[celli] = srcCelli;

            if
            (
                srcCelli != -1
             && ws_.holeTypes[srcCellMap[srcCelli]] != HOLE
             && betterDonor(tgtI, ws_.donorZone[celli], srcI)
            )
            {
                ws_.stencil[celli].setSize(1);
                ws_.stencil[celli][0] =
                    ws_.globalCells.toGlobal(srcCellMap[srcCelli]);
                ws_.donorZone[celli] = srcI;
            }
        }
    }
}


void Foam::cellCellStencils::octreeInverseDistance::searchDonors
(
    const labelUList& cells,
    const bool local
)
{
    if (local)
    {
        findDonors(cells);
    }
    if (Pstream::parRun())
    {
        findRemoteDonors(cells);
    }
    ws_.queried.set(cells);
}


Foam::labelList
Foam::cellCellStencils::octreeInverseDistance::donorCandidates() const
{
    const labelList& allCellTypes = ws_.cellTypes;
    const bitSet& isOversetPatchCell = ws_.isOversetPatchCell;
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();

    bitSet candidate(mesh_.nCells());

    forAll(allCellTypes, celli)
    {
        const label prevType =
            celli < cellTypes_.size() ? cellTypes_[celli] : CALCULATED;
        if
        (
            needsDonor
            (
                allCellTypes[celli], prevType, isOversetPatchCell[celli]
            )
        )
        {
            candidate.set(celli);
        }
    }

    // Next to a hole, across internal and coupled faces
    for (label facei = 0; facei < nInternal; ++facei)
    {
        const bool ownHole = (allCellTypes[own[facei]] == HOLE);
        const bool neiHole = (allCellTypes[nei[facei]] == HOLE);
        if (ownHole && !neiHole)
        {
            candidate.set(nei[facei]);
        }
        else if (neiHole && !ownHole)
        {
            candidate.set(own[facei]);
        }
    }

    labelList nbrTypes;
    syncTools::swapBoundaryCellList(mesh_, allCellTypes, nbrTypes);
    for (label facei = nInternal; facei < mesh_.nFaces(); ++facei)
    {
        const label celli = own[facei];
        if
        (
            nbrTypes[facei - nInternal] == HOLE
         && allCellTypes[celli] != HOLE
        )
        {
            candidate.set(celli);
        }
    }

    return candidate.toc();
}


void Foam::cellCellStencils::octreeInverseDistance::walkFrontResolved
(
    const bool localDone
)
{
    while (true)
    {
        walkFront
        (
            settings_.layerRelax(), ws_.stencil, ws_.cellTypes, ws_.weight
        );

        if (localDone && !Pstream::parRun())
        {
            return;
        }

        // Cells whose type the walk set (from their stencil or its
        // absence) that were not searched for donors
        DynamicList<label> unresolved;
        forAll(ws_.cellTypes, celli)
        {
            if
            (
                ws_.cellTypes[celli] != ws_.floodTypes[celli]
             && !ws_.queried[celli]
            )
            {
                unresolved.append(celli);
            }
        }

        if (returnReduce(unresolved.empty(), andOp<bool>()))
        {
            return;
        }

        searchDonors(unresolved, !localDone);

        // Again from the flood-filled types
        ws_.cellTypes = ws_.floodTypes;
        ws_.weight = Zero;
    }
}


void Foam::cellCellStencils::octreeInverseDistance::findAllDonors()
{
    for (const zoneDonorSearch& search : zoneSearch_)
    {
        search.resetCounters();
    }

    // Donors (full: every cell on this rank) for the cells whose donors
    // matter, on this rank (incremental) and the others (parallel); the
    // donors must not be holes of the hole cutting
    ws_.holeTypes = ws_.cellTypes;
    nQueriesSent_ = 0;
    nQueriesRetried_ = 0;
    nQueriesAnswered_ = 0;
    nDonorSearched_ = 0;
    if (!ws_.incremental)
    {
        findDonors(identity(mesh_.nCells()));
    }
    if (ws_.incremental || Pstream::parRun())
    {
        searchDonors(donorCandidates(), ws_.incremental);
    }
}


void Foam::cellCellStencils::octreeInverseDistance::classifyCells()
{
    // As the stock stencil: an overset-patch cell is interpolated if it
    // has a donor, else a hole (an orphan); so is a cell that was a hole
    // and is calculated now
    ws_.orphans =
        findOrphans(ws_.cellTypes, ws_.isOversetPatchCell, ws_.stencil);

    forAll(ws_.cellTypes, celli)
    {
        label& type = ws_.cellTypes[celli];

        if
        (
            needsDonor(type, cellTypes_[celli], ws_.isOversetPatchCell[celli])
        )
        {
            if (ws_.stencil[celli].size())
            {
                type = INTERPOLATED;
            }
            else
            {
                type = HOLE;
                ws_.stencil[celli].clear();
            }
        }
    }

    // Unreachable regions become holes; fringe layers around the holes
    floodCounts_ = flood_.apply(ws_.globalCells, ws_.stencil, ws_.cellTypes);

    ws_.floodTypes = ws_.cellTypes;
    walkFrontResolved(!ws_.incremental);
}



// ************************************************************************* //
