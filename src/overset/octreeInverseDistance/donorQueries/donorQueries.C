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

#include "donorQueries.H"
#include "mapDistribute.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::donorQueries::donorQueries(const label nProcs)
:
    send_(nProcs)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::donorQueries::add
(
    const label celli,
    const label zonei,
    const labelPair& procSeed,
    const point& p
)
{
    send_[procSeed.first()].append(cell.size());
    cell.append(celli);
    zone.append(zonei);
    proc.append(procSeed.first());
    points.append(p);
    seed.append(procSeed.second());
}


Foam::autoPtr<Foam::mapDistribute> Foam::donorQueries::map()
{
    labelListList send(send_.size());
    forAll(send, proci)
    {
        send[proci].transfer(send_[proci]);
    }

    labelList recvSizes;
    Pstream::exchangeSizes(send, recvSizes);

    labelListList constructMap(Pstream::nProcs());
    label constructSize = 0;
    forAll(constructMap, proci)
    {
        constructMap[proci] = identity(recvSizes[proci], constructSize);
        constructSize += recvSizes[proci];
    }
    return autoPtr<mapDistribute>
    (
        new mapDistribute
        (
            constructSize,
            std::move(send),
            std::move(constructMap)
        )
    );
}


// ************************************************************************* //
