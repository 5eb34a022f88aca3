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
    octreeInverseDistance: the per-step report (cell types, the update's
    work, the stencil checksum, per-zone search figures, traffic: global
    sums, with log or debug) and the orphans.

\*---------------------------------------------------------------------------*/

#include "octreeInverseDistanceCellCellStencil.H"
#include "cellSet.H"
#include "Time.H"

#include <cstdio>
#include <string>

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

uint64_t Foam::cellCellStencils::octreeInverseDistance::stencilChecksum() const
{
    uint64_t sum = 0;
    for (const label celli : interpolationCells_)
    {
        uint64_t h = 14695981039346656037ull;
        const label globalCelli = ws_.globalCells.toGlobal(celli);
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


void Foam::cellCellStencils::octreeInverseDistance::reportOrphans
() const
{
    const labelList& orphans = ws_.orphans;
    const label nOrphans = returnReduce(orphans.size(), sumOp<label>());

    if (nOrphans)
    {
        // A few locations from every rank
        const pointField& cc = mesh_.cellCentres();
        const labelList& zoneID = this->zoneID();
        const label nShow = min(orphans.size(), nOrphansShown);

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
            << mesh_.time().timeName() << "; at most " << nOrphansShown << " per rank:" << nl;
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


void Foam::cellCellStencils::octreeInverseDistance::logStep
(
    const bool rebuilt
) const
{
    const labelList nCells(count(3, cellTypes_));
    const uint64_t checksum = stencilChecksum();
    Info<< type() << " : calculated " << nCells[CALCULATED]
        << " interpolated " << nCells[INTERPOLATED]
        << " hole " << nCells[HOLE]
        << " orphan " << returnReduce(ws_.orphans.size(), sumOp<label>())
        << " stencil " << (rebuilt ? "rebuilt" : "reused")
        << " (rebuilt " << nStencilBuilt_
        << " reused " << nStencilReused_ << ")" << nl << incrIndent
        << indent << "holes " << ws_.mode << ": hole test "
        << returnReduce(nHoleTested_, sumOp<label>())
        << " cells, donor search "
        << returnReduce(nDonorSearched_, sumOp<label>())
        << " cells; stencil checksum " << word(checksumHex(checksum))
        << nl
        << indent << "flood fill: regions "
        << returnReduce(floodCounts_.regions, sumOp<label>())
        << " rounds " << floodCounts_.rounds
        << " holes made "
        << returnReduce(floodCounts_.holes, sumOp<label>()) << nl;
    forAll(zoneSearch_, zonei)
    {
        const zoneDonorSearch& s = zoneSearch_[zonei];
        Info<< indent << "donor zone " << zonei
            << " : rigid fit residual " << zoneResidual_[zonei]
            << " walk " << returnReduce(s.nWalk(), sumOp<label>())
            << " octree " << returnReduce(s.nOctree(), sumOp<label>())
            << " outside " << returnReduce(s.nOutside(), sumOp<label>())
            << " corrected " << returnReduce(s.nCorrected(), sumOp<label>())
            << nl;
    }
    if (Pstream::parRun())
    {
        label nLocal = 0;
        for (const patchVoxelMap::blockedVoxels& v : patchVoxels_)
        {
            nLocal += v.voxels.size();
        }
        Info<< indent << "sent: patch voxels "
            << returnReduce(voxelExchange_.nSent(), sumOp<label>())
            << " donor queries "
            << returnReduce(nQueriesSent_, sumOp<label>())
            << " (second exchange "
            << returnReduce(nQueriesRetried_, sumOp<label>()) << ")"
            << " answered per rank (max) "
            << returnReduce(nQueriesAnswered_, maxOp<label>()) << nl
            << indent << "patch voxels per rank (max): own "
            << returnReduce(nLocal, maxOp<label>())
            << " tested one by one against other ranks' boxes "
            << returnReduce(voxelExchange_.nScanned(), maxOp<label>())
            << nl;
    }
    Info<< decrIndent << endl;
}


Foam::labelList
Foam::cellCellStencils::octreeInverseDistance::findOrphans
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


void Foam::cellCellStencils::octreeInverseDistance::report
(
    const bool rebuilt
) const
{
    if (settings_.log() || debug)
    {
        logStep(rebuilt);
    }
    reportOrphans();
}



// ************************************************************************* //
