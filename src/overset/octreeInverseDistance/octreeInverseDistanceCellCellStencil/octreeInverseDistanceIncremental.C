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
    octreeInverseDistance: the incremental donor search: donors only for the
    cells whose donors matter (need one, border a hole, or are reached by
    the fringe walk).

\*---------------------------------------------------------------------------*/

#include "octreeInverseDistanceCellCellStencil.H"
#include "globalIndex.H"
#include "syncTools.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cellCellStencils::octreeInverseDistance::searchDonors
(
    const labelUList& cells,
    const bool local,
    const globalIndex& globalCells,
    const labelList& allCellTypes,
    labelListList& allStencil,
    labelList& allDonor,
    bitSet& queried
)
{
    if (local)
    {
        findDonors(cells, globalCells, allCellTypes, allStencil, allDonor);
    }
    if (Pstream::parRun())
    {
        findRemoteDonors
        (
            cells, globalCells, allCellTypes, allStencil, allDonor
        );
    }
    queried.set(cells);
}


Foam::labelList
Foam::cellCellStencils::octreeInverseDistance::donorCandidates
(
    const labelList& allCellTypes,
    const bitSet& isOversetPatchCell
) const
{
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
    const bool localDone,
    const globalIndex& globalCells,
    const labelList& holeTypes,
    const labelList& floodTypes,
    labelList& allCellTypes,
    labelListList& allStencil,
    labelList& allDonor,
    scalarField& allWeight,
    bitSet& queried
)
{
    while (true)
    {
        walkFront(layerRelax_, allStencil, allCellTypes, allWeight);

        if (localDone && !Pstream::parRun())
        {
            return;
        }

        // Cells whose type the walk set (from their stencil or its
        // absence) that were not searched for donors
        DynamicList<label> unresolved;
        forAll(allCellTypes, celli)
        {
            if (allCellTypes[celli] != floodTypes[celli] && !queried[celli])
            {
                unresolved.append(celli);
            }
        }

        if (returnReduce(unresolved.empty(), andOp<bool>()))
        {
            return;
        }

        searchDonors
        (
            unresolved,
            !localDone,
            globalCells,
            holeTypes,
            allStencil,
            allDonor,
            queried
        );

        // Again from the flood-filled types
        allCellTypes = floodTypes;
        allWeight = Zero;
    }
}


// ************************************************************************* //
