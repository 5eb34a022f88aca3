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

#include "compactInterpolation.H"
#include "mapDistribute.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::compactInterpolation::compactLayout
(
    const mapDistribute& map,
    const label nLocal
)
{
    if (map.subHasFlip() || map.constructHasFlip())
    {
        return false;
    }
    const label me = Pstream::myProcNo();
    const labelList& subMe = map.subMap()[me];
    const labelList& constructMe = map.constructMap()[me];
    if (subMe != constructMe)
    {
        return false;
    }
    for (const label slot : constructMe)
    {
        if (slot >= nLocal)
        {
            return false;
        }
    }
    forAll(map.constructMap(), proci)
    {
        if (proci == me)
        {
            continue;
        }
        for (const label slot : map.constructMap()[proci])
        {
            if (slot < nLocal)
            {
                return false;
            }
        }
    }
    return true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::compactInterpolation::compactInterpolation
(
    const cellCellStencil& stencil
)
:
    nLocal_(stencil.cellStencil().size()),
    sendCells_(),
    remote_(),
    valid_(compactLayout(stencil.cellInterpolationMap(), nLocal_))
{
    if (!valid_)
    {
        return;
    }
    const mapDistribute& map = stencil.cellInterpolationMap();
    const label me = Pstream::myProcNo();
    const label nProcs = map.subMap().size();

    labelListList subMap(nProcs);
    labelListList constructMap(nProcs);
    DynamicList<label> send;
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (proci == me)
        {
            continue;
        }
        const labelList& cells = map.subMap()[proci];
        subMap[proci] = identity(cells.size(), send.size());
        send.append(cells);
        constructMap[proci] = map.constructMap()[proci];
        for (label& slot : constructMap[proci])
        {
            slot -= nLocal_;
        }
    }
    sendCells_.transfer(send);
    remote_ = mapDistributeBase
    (
        map.constructSize() - nLocal_,
        std::move(subMap),
        std::move(constructMap)
    );
}


// ************************************************************************* //
