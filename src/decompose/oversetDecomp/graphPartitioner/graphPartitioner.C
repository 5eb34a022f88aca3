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

#include "graphPartitioner.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::graphPartitioner::graphPartitioner(const oversetGraphSettings& settings)
:
    settings_(settings)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::graphPartitioner::partition
(
    const couplingGraph& graph,
    const label nParts
) const
{
    if (nParts == 1 || graph.nCells() == 0)
    {
        return labelList(graph.nCells(), Zero);
    }
    labelList part
    (
        settings_.partitioner() == library::metis
      ? metis(graph, nParts)
      : scotch(graph, nParts)
    );
    labelList cells(nParts, Zero);
    for (const label p : part)
    {
        ++cells[p];
    }
    const label nEmpty = std::count(cells.begin(), cells.end(), 0);
    if (nEmpty)
    {
        WarningInFunction
            << libraryName() << " left " << nEmpty << " of " << nParts
            << " parts empty (cells per part " << cells << ", a graph of "
            << graph.nCells() << " cells): fewer balance constraints"
            << " (poseGroups 0), a larger oversetImbalance or the scotch"
            << " partitioner may fill them" << endl;
    }
    return part;
}


// ************************************************************************* //
