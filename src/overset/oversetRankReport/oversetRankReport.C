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

#include "oversetRankReport.H"
#include "cellCellStencilObject.H"
#include "processorPolyPatch.H"
#include "IOmanip.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::oversetRankReport::prefix("oversetRankReport:");

const Foam::FixedList<Foam::word, Foam::oversetRankReport::N_COLUMNS>
Foam::oversetRankReport::columnNames
({
    "cells",
    "procFaces",
    "procPatches",
    "haloBytes",
    "acceptors",
    "remote",
    "mixed",
    "allRemote",
    "remoteSlots",
    "sent",
    "received",
    "sendRanks",
    "recvRanks"
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Width of the first column (rank, total, max, mean)
constexpr int labelWidth = 6;

//- Width of the other columns
constexpr int columnWidth = 12;

//- One line of the table: the prefix, a label and the values
template<class T>
void writeLine
(
    Ostream& os,
    const word& label,
    const FixedList<T, oversetRankReport::N_COLUMNS>& values
)
{
    os  << oversetRankReport::prefix << ' ' << setw(labelWidth) << label;
    for (const T& value : values)
    {
        os  << ' ' << setw(columnWidth) << value;
    }
    os  << nl;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::oversetRankReport::countMesh(const polyMesh& mesh, row& counts)
{
    counts[CELLS] += mesh.nCells();
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<processorPolyPatch>(pp))
        {
            counts[PROC_FACES] += pp.size();
            ++counts[PROC_PATCHES];
        }
    }
    counts[HALO_BYTES] = sizeof(scalar)*counts[PROC_FACES];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::oversetRankReport::oversetRankReport(const fvMesh& mesh)
:
    timeName_(mesh.time().timeName()),
    stencilName_
    (
        mesh.schemesDict().subDict("oversetInterpolation").get<word>("method")
    ),
    rows_(Pstream::nProcs(), row(Zero))
{
    const label rank = Pstream::myProcNo();
    const cellCellStencilObject& overlap = Stencil::New(mesh);
    const mapDistribute& map = overlap.cellInterpolationMap();

    // The rank each slot of the constructed list comes from
    labelList slotRank(mesh.nCells(), rank);
    map.distribute(slotRank);

    row& counts = rows_[rank];
    countMesh(mesh, counts);
    countAcceptors
    (
        overlap.cellTypes(),
        overlap.cellStencil(),
        slotRank,
        rank,
        counts
    );
    countExchange(map, rank, counts);

    Pstream::gatherList(rows_);
    Pstream::scatterList(rows_);
}


Foam::oversetRankReport::oversetRankReport
(
    const word& timeName,
    const word& stencilName,
    const List<row>& rows
)
:
    timeName_(timeName),
    stencilName_(stencilName),
    rows_(rows)
{}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::oversetRankReport::countAcceptors
(
    const labelUList& cellTypes,
    const labelListList& stencil,
    const labelUList& slotRank,
    const label rank,
    row& counts
)
{
    forAll(cellTypes, celli)
    {
        if (cellTypes[celli] != cellCellStencil::INTERPOLATED)
        {
            continue;
        }
        ++counts[ACCEPTORS];

        const labelList& slots = stencil[celli];
        label nRemote = 0;
        for (const label slot : slots)
        {
            if (slotRank[slot] != rank)
            {
                ++nRemote;
            }
        }
        counts[REMOTE_SLOTS] += nRemote;
        if (nRemote)
        {
            ++counts[REMOTE];
            ++counts[nRemote == slots.size() ? ALL_REMOTE : MIXED];
        }
    }
}


void Foam::oversetRankReport::countExchange
(
    const mapDistributeBase& map,
    const label rank,
    row& counts
)
{
    forAll(map.subMap(), proci)
    {
        const label n = map.subMap()[proci].size();
        if (proci != rank && n)
        {
            counts[SENT] += n;
            ++counts[SEND_RANKS];
        }
    }
    forAll(map.constructMap(), proci)
    {
        const label n = map.constructMap()[proci].size();
        if (proci != rank && n)
        {
            counts[RECEIVED] += n;
            ++counts[RECV_RANKS];
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::oversetRankReport::row Foam::oversetRankReport::total() const
{
    row sum(Zero);
    for (const row& r : rows_)
    {
        forAll(sum, coli)
        {
            sum[coli] += r[coli];
        }
    }
    return sum;
}


Foam::oversetRankReport::row Foam::oversetRankReport::max() const
{
    row largest(Zero);
    for (const row& r : rows_)
    {
        forAll(largest, coli)
        {
            largest[coli] = Foam::max(largest[coli], r[coli]);
        }
    }
    return largest;
}


Foam::scalar Foam::oversetRankReport::cellImbalance() const
{
    const label nCells = total()[CELLS];
    if (!nCells)
    {
        return 1;
    }
    return scalar(max()[CELLS])*rows_.size()/nCells;
}


Foam::scalar Foam::oversetRankReport::remoteShare() const
{
    const row sum(total());
    if (!sum[ACCEPTORS])
    {
        return 0;
    }
    return scalar(sum[REMOTE])/sum[ACCEPTORS];
}


void Foam::oversetRankReport::write(Ostream& os) const
{
    os  << prefix << " time " << timeName_ << " stencil " << stencilName_
        << " ranks " << rows_.size() << nl;
    writeLine(os, "rank", columnNames);
    forAll(rows_, ranki)
    {
        writeLine(os, Foam::name(ranki), rows_[ranki]);
    }

    const row sum(total());
    writeLine(os, "total", sum);
    writeLine(os, "max", max());
    FixedList<scalar, N_COLUMNS> mean;
    forAll(mean, coli)
    {
        mean[coli] = scalar(sum[coli])/Foam::max(rows_.size(), 1);
    }
    writeLine(os, "mean", mean);

    os  << prefix << " cellImbalance " << cellImbalance()
        << " remoteShare " << remoteShare() << endl;
}


// ************************************************************************* //
