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
    graphPartitioner::scotch: SCOTCH_graphPart, one weight per vertex (cell
    weight plus oversetWork times the overset work per pose), weighted
    edges, the balance strategy.

\*---------------------------------------------------------------------------*/

#include "graphPartitioner.H"
#include <cstdio>
#include <cstdint>
#include <vector>
extern "C"
{
#include <scotch.h>
}

static_assert
(
    sizeof(SCOTCH_Num) == sizeof(Foam::label),
    "SCOTCH_Num and OpenFOAM label differ in width"
);

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::graphPartitioner::scotch
(
    const couplingGraph& graph,
    const label nParts
) const
{
    const label n = graph.nCells();
    const scalar workScale = settings_.oversetWork()/max(1, graph.nPoses());
    const scalar cellScale = 100;
    std::vector<SCOTCH_Num> velotab(n);
    for (label i = 0; i < n; ++i)
    {
        velotab[i] = SCOTCH_Num
        (
            cellScale*(graph.cellWeight()[i] + workScale*graph.oversetWork()[i])
          + 0.5
        );
    }

    // Deterministic: a context of its own, one random seed, no
    // thread-order effects
    SCOTCH_Context context;
    SCOTCH_Graph scotchGraph;
    SCOTCH_Graph boundGraph;
    SCOTCH_Strat strategy;
    SCOTCH_contextInit(&context);
    SCOTCH_graphInit(&scotchGraph);
    SCOTCH_graphInit(&boundGraph);
    SCOTCH_stratInit(&strategy);
    int status = SCOTCH_contextOptionSetNum
    (
        &context, SCOTCH_OPTIONNUMDETERMINISTIC, 1
    );
    status = status ? status : SCOTCH_contextRandomClone(&context);
    SCOTCH_contextRandomSeed(&context, 1);
    status = status ? status : SCOTCH_graphBuild
    (
        &scotchGraph,
        0,
        n,
        graph.xadj().cdata(),
        graph.xadj().cdata() + 1,
        velotab.data(),
        nullptr,
        graph.adjncy().size(),
        graph.adjncy().cdata(),
        graph.adjwgt().cdata()
    );
    status = status ? status : SCOTCH_graphCheck(&scotchGraph);
    status = status ? status : SCOTCH_stratGraphMapBuild
    (
        &strategy, SCOTCH_STRATBALANCE, nParts, settings_.imbalance()
    );
    status = status ? status : SCOTCH_contextBindGraph
    (
        &context, &scotchGraph, &boundGraph
    );
    labelList part(n);
    status = status ? status : SCOTCH_graphPart
    (
        &boundGraph, nParts, &strategy, part.data()
    );
    SCOTCH_graphExit(&boundGraph);
    SCOTCH_stratExit(&strategy);
    SCOTCH_graphExit(&scotchGraph);
    SCOTCH_contextExit(&context);
    if (status)
    {
        FatalErrorInFunction
            << "Scotch failed (status " << status << ") on " << n
            << " cells into " << nParts << " parts" << exit(FatalError);
    }
    return part;
}


// ************************************************************************* //
