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
    octreeInverseDistance: the stencil.  The inverse-distance stencil and
    weights of the stock createStencil (the donor and its valid face
    neighbours, weights from the acceptor's centre), computed in one pass
    from the single donors; the compact stencil and its mapDistribute are
    kept from the previous step while the addressing does not change.

\*---------------------------------------------------------------------------*/

#include "octreeInverseDistanceCellCellStencil.H"
#include "mapDistribute.H"
#include "OStringStream.H"
#include "dynamicOversetFvMesh.H"
#include "oversetFvPatchField.H"
#include "Time.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cellCellStencils::octreeInverseDistance::gatherDonorStencils
(
    labelList& slots,
    List<Map<label>>& compactMap,
    labelListList& donorCellCells,
    pointListList& donorCellCentres
)
{
    const label nCells = mesh_.nCells();

    // The donors in compact numbering (local cells first, then the remote
    // ones), and the map that brings a donor's data to its acceptors
    slots = donorGlobal_;
    const mapDistribute donorMap(ws_.globalCells, slots, compactMap);

    // The local cells that are donors, here or on another rank
    bitSet& isDonor = ws_.isDonor;
    isDonor.reset();
    isDonor.resize(nCells);
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
    boolList& isValidDonor = ws_.isValidDonor;
    isValidDonor.setSize(nCells);
    forAll(cellTypes_, celli)
    {
        isValidDonor[celli] = (cellTypes_[celli] != HOLE);
    }

    donorCellCells.setSize(nCells);
    donorCellCentres.setSize(nCells);
    globalCellCells
    (
        ws_.globalCells,
        mesh_,
        isValidDonor,
        isDonor.toc(),
        donorCellCells,
        donorCellCentres
    );
    donorMap.distribute(donorCellCells);
    donorMap.distribute(donorCellCentres);
}


bool Foam::cellCellStencils::octreeInverseDistance::addressingUnchanged
(
    const labelList& slots,
    const labelListList& donorCellCells
) const
{
    // Same interpolated cells with the same stencils
    const label nCells = mesh_.nCells();
    const labelList& acceptors = interpolationCells_;

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
    return same;
}


void Foam::cellCellStencils::octreeInverseDistance::releaseEmptyStencils
(
    const labelList& slots,
    const labelListList& donorCellCells
)
{
    // Acceptors left without a stencil: the donor became a hole after the
    // donor search (flood fill or fringe walk) and so did all its
    // neighbours.  The stock stencil keeps them interpolated from nothing:
    // dynamicOversetFvMesh then scales their row by 1 - weight = 0 and adds
    // no donor, the diagonal is 0 and the smoother divides by it (a BW
    // hover died of it at t = 0.9436 s).  Here their weight is 0: the
    // cells are solved as calculated cells this step
    const label nCells = mesh_.nCells();
    const labelList& acceptors = interpolationCells_;
    const pointField& cc = mesh_.cellCentres();

    DynamicList<label> empty;
    forAll(acceptors, i)
    {
        if (donorCellCells[slots[i]].empty())
        {
            empty.append(i);
        }
    }
    const label nEmpty = returnReduce(empty.size(), sumOp<label>());
    if (!nEmpty)
    {
        return;
    }

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
    for (const label i : empty)
    {
        cellInterpolationWeight_[acceptors[i]] = 0;
    }

    WarningInFunction
        << nEmpty << " interpolated cells have an empty stencil"
        << " (their donor and its neighbours are holes) at time "
        << mesh_.time().timeName() << ": solved as calculated cells (weight"
        << " 0) this step; on this rank:"
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


bool Foam::cellCellStencils::octreeInverseDistance::createStencilOnePass()
{
    const label nCells = mesh_.nCells();
    const labelList& acceptors = interpolationCells_;
    const pointField& cc = mesh_.cellCentres();

    labelList slots;
    List<Map<label>> compactMap;
    labelListList donorCellCells;
    pointListList donorCellCentres;
    gatherDonorStencils(slots, compactMap, donorCellCells, donorCellCentres);

    const bool same = addressingUnchanged(slots, donorCellCells);

    releaseEmptyStencils(slots, donorCellCells);

    // Weights from the acceptor's centre (stock stencilWeights)
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
        new mapDistribute(ws_.globalCells, cellStencil_, compactMap)
    );
    ++nStencilBuilt_;
    return true;
}


bool Foam::cellCellStencils::octreeInverseDistance::buildStencil()
{
    // The final types (the previous ones go to the workspace)
    cellTypes_.swap(ws_.cellTypes);

    forAll(cellTypes_, celli)
    {
        if (cellTypes_[celli] == INTERPOLATED)
        {
            if (ws_.stencil[celli].size() != 1)
            {
                FatalErrorInFunction
                    << "interpolated cell " << celli << " has "
                    << ws_.stencil[celli].size() << " donors instead of 1"
                    << abort(FatalError);
            }
            ws_.interpolated.append(celli);
        }
    }
    interpolationCells_ = ws_.interpolated;
    donorGlobal_.setSize(interpolationCells_.size());
    forAll(interpolationCells_, i)
    {
        donorGlobal_[i] = ws_.stencil[interpolationCells_[i]][0];
    }

    UList<scalar>& weight = cellInterpolationWeight_;
    weight.swap(ws_.weight);

    // The inverse-distance stencil around each donor (the stock
    // createStencil's result, one pass, addressing kept if unchanged; the
    // weight of an acceptor left without one set to 0), then the weight's
    // boundary values
    const bool rebuilt = createStencilOnePass();
    dynamicOversetFvMesh::correctBoundaryConditions
    <
        volScalarField,
        oversetFvPatchField<scalar>
    >(cellInterpolationWeight_.boundaryFieldRef(), false);
    return rebuilt;
}



// ************************************************************************* //
