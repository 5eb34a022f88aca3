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
    octreeInverseDistance: what crosses the ranks.  Patch voxels go only to
    the ranks whose parts of other zones they may cut (the boxes here, the
    exchange in Foam::patchVoxelExchange), donor queries only
    for the cells whose donors matter (Foam::donorQueries): to the rank that
    held the donor at the previous update alone while its cached box holds
    the cell, else (or if it no longer holds the cell, in a second exchange)
    to every rank whose cached box of the zone, in the zone's frame, does.

\*---------------------------------------------------------------------------*/

#include "octreeInverseDistanceCellCellStencil.H"
#include "globalIndex.H"
#include "mapDistribute.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::List<Foam::treeBoundBoxList>>
Foam::cellCellStencils::octreeInverseDistance::voxelTargets() const
{
    const label nZones = zoneSearch_.size();
    List<List<treeBoundBoxList>> tgtBb(Pstream::nProcs());

    forAll(tgtBb, proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        tgtBb[proci].setSize(nZones);
        for (label zonei = 0; zonei < nZones; ++zonei)
        {
            // The cached boxes of that rank's parts of the other zones, at
            // the current pose, grown by the tolerance the hole test adds
            for (label tgti = 0; tgti < nZones; ++tgti)
            {
                if (tgti == zonei)
                {
                    continue;
                }
                treeBoundBox bb
                (
                    zoneSearch_[tgti].toCurrent(procBb_[tgti][proci])
                );
                if (!bb.empty())
                {
                    bb.min() -= smallVec_;
                    bb.max() += smallVec_;
                    tgtBb[proci][zonei].append(bb);
                }
            }
        }
    }
    return tgtBb;
}


void Foam::cellCellStencils::octreeInverseDistance::answerQueries
(
    const pointField& points,
    const labelList& zones,
    const labelList& seeds,
    labelList& donors,
    labelList& found
) const
{
    donors.setSize(points.size());
    donors = -1;
    found.setSize(points.size());
    found = -1;
    forAll(points, i)
    {
        const label srci = zones[i];
        const zoneDonorSearch& search = zoneSearch_[srci];
        const label subCelli =
            currentDonor
            (
                srci,
                search.toCurrent(points[i]),
                search.findCell(points[i], seeds[i])
            );
        if (subCelli != -1)
        {
            found[i] = subCelli;
            const label celli = zoneParts_[srci].cellMap()[subCelli];
            if (ws_.holeTypes[celli] != HOLE)
            {
                donors[i] = ws_.globalCells.toGlobal(celli);
            }
        }
    }
}


void Foam::cellCellStencils::octreeInverseDistance::queryOtherRanks
(
    const label celli,
    const label srci,
    const point& p0,
    const label skipProci,
    donorQueries& q
) const
{
    // No seed: a rank that found the cell last time is asked alone
    forAll(procBb_[srci], proci)
    {
        if
        (
            proci != Pstream::myProcNo()
         && proci != skipProci
         && procBb_[srci][proci].contains(p0)
        )
        {
            q.add(celli, srci, labelPair(proci, -1), p0);
        }
    }
}


void Foam::cellCellStencils::octreeInverseDistance::collectRemoteQueries
(
    const labelUList& cells,
    donorQueries& q
) const
{
    const label nZones = zoneSearch_.size();
    const labelList& zoneID = this->zoneID();
    const pointField& cc = mesh_.cellCentres();

    for (const label celli : cells)
    {
        const label tgti = zoneID[celli];
        const label donor = ws_.donorZone[celli];

        for (label srci = 0; srci < nZones; ++srci)
        {
            // Only a donor zone better than the one found can change it
            if
            (
                srci == tgti
             || (donor != -1 && !betterDonor(tgti, donor, srci))
            )
            {
                continue;
            }

            // The rank that held the donor last time, alone, while its box
            // holds the centre; else every rank whose box holds it
            const labelPair& prev = prevRemote_[srci][celli];
            const point p0(zoneSearch_[srci].toReference(cc[celli]));
            if (prev.first() != -1 && procBb_[srci][prev.first()].contains(p0))
            {
                q.add(celli, srci, prev, p0);
            }
            else
            {
                queryOtherRanks(celli, srci, p0, -1, q);
            }
        }
    }
}


void Foam::cellCellStencils::octreeInverseDistance::collectRetries
(
    const donorQueries& asked,
    const labelUList& found,
    donorQueries& q
)
{
    const pointField& cc = mesh_.cellCentres();
    forAll(asked.cell, i)
    {
        // Asked alone (with a seed) and no longer there: no longer first
        if (asked.seed[i] != -1 && found[i] == -1)
        {
            const label celli = asked.cell[i];
            const label srci = asked.zone[i];
            prevRemote_[srci][celli] = labelPair(-1, -1);
            queryOtherRanks
            (
                celli,
                srci,
                zoneSearch_[srci].toReference(cc[celli]),
                asked.proc[i],
                q
            );
        }
    }
}


void Foam::cellCellStencils::octreeInverseDistance::exchangeQueries
(
    donorQueries& q,
    labelList& found
)
{
    const label nQueries = q.size();
    nQueriesSent_ += nQueries;

    // The map: send the queries, answers come back by reverseDistribute
    const autoPtr<mapDistribute> mapPtr(q.map());
    const mapDistribute& map = *mapPtr;

    pointField points(std::move(q.points));
    labelList zones(q.zone);
    labelList seeds(q.seed);
    map.distribute(points);
    map.distribute(zones);
    map.distribute(seeds);
    nQueriesAnswered_ += points.size();

    labelList donors;
    answerQueries(points, zones, seeds, donors, found);
    map.reverseDistribute(nQueries, donors);
    map.reverseDistribute(nQueries, found);

    // Keep the best donor zone, the lowest rank within a zone (as stock)
    const labelList& zoneID = this->zoneID();
    for (label i = 0; i < nQueries; ++i)
    {
        const label celli = q.cell[i];
        const label srci = q.zone[i];

        if (found[i] != -1)
        {
            prevRemote_[srci][celli] = labelPair(q.proc[i], found[i]);
        }
        if
        (
            donors[i] != -1
         && betterDonor(zoneID[celli], ws_.donorZone[celli], srci)
        )
        {
            ws_.stencil[celli].setSize(1);
            ws_.stencil[celli][0] = donors[i];
            ws_.donorZone[celli] = srci;
        }
    }
}


void Foam::cellCellStencils::octreeInverseDistance::findRemoteDonors
(
    const labelUList& cells
)
{
    // Queries: (cell, donor zone, rank) with the point in the donor zone's
    // frame (the same transform on every rank) and the walk's seed there;
    // first to the rank that held the donor last time
    donorQueries q(Pstream::nProcs());
    collectRemoteQueries(cells, q);
    labelList found;
    exchangeQueries(q, found);

    // Where that rank no longer holds the cell: the other ranks
    donorQueries retries(Pstream::nProcs());
    collectRetries(q, found, retries);
    nQueriesRetried_ += retries.size();
    if (returnReduce(retries.size() > 0, orOp<bool>()))
    {
        exchangeQueries(retries, found);
    }
}


// ************************************************************************* //
