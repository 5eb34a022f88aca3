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
    octreeInverseDistance: the incremental update.  The hole test only for
    the cells the PATCH voxels can reach (bins of each zone's cells in the
    zone's own frame), donors only for the cells whose donors matter
    (need one, border a hole, or are reached by the fringe walk).

\*---------------------------------------------------------------------------*/

#include "octreeInverseDistanceCellCellStencil.H"
#include "globalIndex.H"
#include "syncTools.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cellCellStencils::octreeInverseDistance::buildBins
(
    const label zonei
)
{
    // The zone's cell centres at the reference pose (sub-mesh order =
    // cellMap order) and bounding radii
    const pointField& cc0 = zoneParts_[zonei].subMesh().cellCentres();
    const scalarField& radius = cellRadius_[zonei];
    const label nCells = cc0.size();

    treeBoundBox& bb = binBb_[zonei];
    labelVector& nDivs = binDivs_[zonei];
    labelList& start = binStart_[zonei];
    labelList& cells = binCells_[zonei];

    bb = treeBoundBox(treeBoundBox::invertedBox);
    forAll(cc0, i)
    {
        bb.add(cc0[i]);
    }
    if (!nCells)
    {
        nDivs = labelVector::one;
        start = labelList(2, Zero);
        cells.clear();
        return;
    }
    bb.inflate(1e-6);

    // About 4 cells a bin
    const vector span(bb.span());
    const scalar h = max
    (
        Foam::cbrt(span.x()*span.y()*span.z()/(nCells/4.0 + 1)),
        VSMALL
    );
    for (direction d = 0; d < 3; ++d)
    {
        nDivs[d] = max(label(1), min(label(span[d]/h), label(256)));
    }

    // A cell goes into every bin its bounding sphere's box (radius grown
    // by sqrt(3), see holeCandidates) meets
    const scalar grow = Foam::sqrt(3.0)*(1 + 1e-6);
    auto range = [&](const label i, labelVector& lo, labelVector& hi)
    {
        const vector r(vector::uniform(grow*radius[i]));
        lo = max(labelVector::zero, index3(bb, nDivs, cc0[i] - r));
        hi = min(nDivs - labelVector::one, index3(bb, nDivs, cc0[i] + r));
    };

    const label nBins = nDivs.x()*nDivs.y()*nDivs.z();
    start = labelList(nBins + 1, Zero);
    labelVector lo, hi;
    for (label pass = 0; pass < 2; ++pass)
    {
        labelList fill;
        if (pass == 1)
        {
            for (label b = 0; b < nBins; ++b)
            {
                start[b + 1] += start[b];
            }
            cells.setSize(start[nBins]);
            fill = SubList<label>(start, nBins);
        }
        for (label i = 0; i < nCells; ++i)
        {
            range(i, lo, hi);
            for (label bi = lo.x(); bi <= hi.x(); ++bi)
            {
                for (label bj = lo.y(); bj <= hi.y(); ++bj)
                {
                    for (label bk = lo.z(); bk <= hi.z(); ++bk)
                    {
                        const label b = index(nDivs, labelVector(bi, bj, bk));
                        if (pass == 0)
                        {
                            ++start[b + 1];
                        }
                        else
                        {
                            cells[fill[b]++] = i;
                        }
                    }
                }
            }
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
    const zoneDonorSearch& search = zoneSearch_[tgtI];
    const treeBoundBox& binBb = binBb_[tgtI];
    const labelVector& binDivs = binDivs_[tgtI];
    const labelList& start = binStart_[tgtI];
    const labelList& cells = binCells_[tgtI];
    const label nCells = cellRadius_[tgtI].size();

    const labelUList& blockList = src.blockList();
    if (!nCells || blockList.empty())
    {
        return labelList();
    }

    // The hole test's margins: the rigid-fit residual (cell centre and
    // radius) and the tolerance; sqrt(3) turns the boxes of the test
    // into balls, which rotate into the zone's frame unchanged
    const scalar m = 4*zoneResidual_[tgtI];
    const scalar grow =
        Foam::sqrt(3.0)*(m + cmptMax(cmptMag(smallVec_))) + m
      + 1e-9*mag(src.bb().span());

    bitSet isCandidate(nCells);
    for (const label blocki : blockList)
    {
        // The block's voxels, grown
        treeBoundBox blockBb(src.blockBox(blocki));
        blockBb.min() -= vector::uniform(grow);
        blockBb.max() += vector::uniform(grow);

        // Its box in the zone's frame, and the bins there
        const treeBoundBox bb0(search.toReference(blockBb));
        if (!bb0.overlaps(binBb))
        {
            continue;
        }
        const labelVector lo
        (
            max(labelVector::zero, index3(binBb, binDivs, bb0.min()))
        );
        const labelVector hi
        (
            min(binDivs - labelVector::one, index3(binBb, binDivs, bb0.max()))
        );
        for (label bi = lo.x(); bi <= hi.x(); ++bi)
        {
            for (label bj = lo.y(); bj <= hi.y(); ++bj)
            {
                for (label bk = lo.z(); bk <= hi.z(); ++bk)
                {
                    const label bin = index(binDivs, labelVector(bi, bj, bk));
                    for (label k = start[bin]; k < start[bin + 1]; ++k)
                    {
                        isCandidate.set(cells[k]);
                    }
                }
            }
        }
    }

    return isCandidate.toc();
}


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
