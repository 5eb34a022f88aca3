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

#include "UIndirectList.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class T>
void Foam::compactInterpolation::interpolate
(
    const cellCellStencil& stencil,
    Field<T>& psi
) const
{
    const labelListList& cellStencil = stencil.cellStencil();
    const List<scalarList>& wghts = stencil.cellInterpolationWeights();
    const labelUList& cellIDs = stencil.interpolationCells();
    const scalarList& factor = stencil.cellInterpolationWeight();

    // The remote donors' values (the exchange is collective: every rank
    // takes part, with or without acceptors)
    List<T> remote(UIndirectList<T>(psi, sendCells_));
    remote_.distribute(remote, UPstream::msgType() + 1);

    // Every acceptor from the values before any is changed (donors can
    // themselves be acceptors), summed in the stencil's order
    List<T> values(cellIDs.size());
    forAll(cellIDs, i)
    {
        const label celli = cellIDs[i];
        const scalarList& w = wghts[celli];
        const labelList& nbrs = cellStencil[celli];

        T s(Zero);
        forAll(nbrs, k)
        {
            const label n = nbrs[k];
            s += w[k]*(n < nLocal_ ? psi[n] : remote[n - nLocal_]);
        }
        values[i] = (1.0 - factor[celli])*psi[celli] + factor[celli]*s;
    }
    forAll(cellIDs, i)
    {
        psi[cellIDs[i]] = values[i];
    }
}


// ************************************************************************* //
