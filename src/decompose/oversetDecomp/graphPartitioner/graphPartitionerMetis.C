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
    graphPartitioner::metis: METIS_PartGraphKway, two constraints per
    vertex (cell weight, overset work) and one per group of kept poses
    (poseGroups), weighted edges.

\*---------------------------------------------------------------------------*/

#include "graphPartitioner.H"
#include <metis.h>
#include <vector>

static_assert
(
    sizeof(idx_t) == sizeof(Foam::label),
    "METIS idx_t and OpenFOAM label differ in width"
);

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::graphPartitioner::metisWeights
(
    const couplingGraph& graph,
    label& nConstraints
) const
{
    // the constraints' columns: cells, the cycle's overset work, and the
    // work of each group of kept poses; columns without work left out.  A
    // group of one pose is that pose's column; larger groups sum
    // consecutive poses
    const labelListList& poseWork = graph.poseWork();
    const label nPoses = poseWork.size();
    const label nGroups = settings_.poseGroups() < 0
        ? nPoses : min(settings_.poseGroups(), nPoses);
    labelListList summed;
    if (nGroups && nGroups < nPoses)
    {
        summed.setSize(nGroups, labelList(graph.nCells(), Zero));
        forAll(poseWork, sample)
        {
            labelList& work = summed[sample*nGroups/nPoses];
            forAll(work, i)
            {
                work[i] += poseWork[sample][i];
            }
        }
    }
    const labelListList& groupWork = nGroups == nPoses ? poseWork : summed;
    DynamicList<const labelList*> used({&graph.cellWeight()});
    if (sum(graph.oversetWork()) > 0)
    {
        used.append(&graph.oversetWork());
    }
    for (const labelList& work : groupWork)
    {
        if (sum(work) > 0)
        {
            used.append(&work);
        }
    }
    nConstraints = used.size();
    labelList vwgt(nConstraints*graph.nCells());
    forAll(used, c)
    {
        forAll(*used[c], i)
        {
            vwgt[nConstraints*i + c] = (*used[c])[i];
        }
    }
    return vwgt;
}


Foam::labelList Foam::graphPartitioner::metis
(
    const couplingGraph& graph,
    const label nParts
) const
{
    idx_t nVertices = graph.nCells();
    idx_t nConstraints = 1;
    labelList vwgt(metisWeights(graph, nConstraints));
    std::vector<real_t> ubvec
    (
        nConstraints,
        real_t(1 + settings_.oversetImbalance())
    );
    ubvec[0] = real_t(1 + settings_.imbalance());
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    options[METIS_OPTION_SEED] = 1;
    options[METIS_OPTION_NCUTS] = 4;

    idx_t nPartsMetis = nParts;
    idx_t edgeCut = 0;
    labelList part(nVertices);
    const int status = METIS_PartGraphKway
    (
        &nVertices,
        &nConstraints,
        const_cast<idx_t*>(graph.xadj().cdata()),
        const_cast<idx_t*>(graph.adjncy().cdata()),
        vwgt.data(),
        nullptr,
        const_cast<idx_t*>(graph.adjwgt().cdata()),
        &nPartsMetis,
        nullptr,
        ubvec.data(),
        options,
        &edgeCut,
        part.data()
    );
    if (status != METIS_OK)
    {
        FatalErrorInFunction
            << "METIS_PartGraphKway failed (status " << status << ") on "
            << nVertices << " cells into " << nParts << " parts"
            << exit(FatalError);
    }
    return part;
}


// ************************************************************************* //
