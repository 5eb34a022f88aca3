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

#include "couplingGraph.H"
#include "decompositionMethod.H"
#include "CompactListList.H"
#include <algorithm>
#include <tuple>
#include <vector>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

// The definition (C++11: a bound reference, as in gtest's EXPECT_EQ, uses it)
constexpr Foam::label Foam::couplingGraph::faceWeight;


Foam::labelList Foam::couplingGraph::integerWeights
(
    const scalarField& weights,
    const label n
)
{
    if (weights.empty())
    {
        return labelList(n, 1);
    }
    const scalar minWeight = min(weights);
    if (weights.size() != n || minWeight <= 0)
    {
        FatalErrorInFunction
            << weights.size() << " cell weights, smallest " << minWeight
            << ": one positive weight per cell (" << n << ") is allowed"
            << exit(FatalError);
    }
    labelList result(n);
    forAll(weights, i)
    {
        result[i] = max(1, label(weights[i]/minWeight + 0.5));
    }
    return result;
}


void Foam::couplingGraph::setRows
(
    const List<labelPair>& edges,
    const labelList& weights,
    const label n
)
{
    std::vector<std::tuple<label, label, label>> rows(edges.size());
    forAll(edges, i)
    {
        rows[i] =
            std::make_tuple(edges[i].first(), edges[i].second(), weights[i]);
    }
    std::sort(rows.begin(), rows.end());

    xadj_.setSize(n + 1);
    adjncy_.setSize(rows.size());
    adjwgt_.setSize(rows.size());
    label nEdges = 0;
    label row = 0;
    xadj_[0] = 0;
    for (const auto& e : rows)
    {
        const label celli = std::get<0>(e);
        const label nbri = std::get<1>(e);
        while (row < celli)
        {
            xadj_[++row] = nEdges;
        }
        if (nbri == celli)
        {
            continue;
        }
        if (nEdges > xadj_[row] && adjncy_[nEdges - 1] == nbri)
        {
            adjwgt_[nEdges - 1] += std::get<2>(e);
        }
        else
        {
            adjncy_[nEdges] = nbri;
            adjwgt_[nEdges++] = std::get<2>(e);
        }
    }
    while (row < n)
    {
        xadj_[++row] = nEdges;
    }
    adjncy_.setSize(nEdges);
    adjwgt_.setSize(nEdges);
}


void Foam::couplingGraph::setPoseWork(const oversetCouplings& couplings)
{
    const labelList& poseStart = couplings.samplePoseStart();
    const labelList& acceptors = couplings.sampleAcceptors();
    const labelList& donorStart = couplings.sampleDonorStart();
    const labelList& donors = couplings.sampleDonors();
    poseWork_.setSize(couplings.nSamples());
    forAll(poseWork_, sample)
    {
        labelList& work = poseWork_[sample];
        work.setSize(nCells(), Zero);
        for (label i = poseStart[sample]; i < poseStart[sample + 1]; ++i)
        {
            ++work[acceptors[i]];
            for (label j = donorStart[i]; j < donorStart[i + 1]; ++j)
            {
                ++work[donors[j]];
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingGraph::couplingGraph
(
    const polyMesh& mesh,
    const oversetCouplings& couplings,
    const scalar couplingWeight,
    const scalarField& weights
)
:
    cellWeight_(integerWeights(weights, mesh.nCells())),
    oversetWork_(mesh.nCells()),
    nPoses_(couplings.nPoses())
{
    const label n = mesh.nCells();
    forAll(oversetWork_, celli)
    {
        oversetWork_[celli] = couplings.acceptorPoses()[celli]
          + couplings.donorPoses()[celli] + couplings.holePoses()[celli];
    }
    setPoseWork(couplings);

    CompactListList<label> cellCells;
    decompositionMethod::calcCellCells
    (
        mesh, identity(n), n, false, cellCells
    );
    const labelList& acceptors = couplings.acceptors();
    const labelList& donors = couplings.donors();
    const labelList& poses = couplings.poses();

    List<labelPair> edges(cellCells.m().size() + 2*acceptors.size());
    labelList edgeWeights(edges.size());
    label nEdges = 0;
    for (label celli = 0; celli < n; ++celli)
    {
        for (const label nbri : cellCells[celli])
        {
            edgeWeights[nEdges] = faceWeight;
            edges[nEdges++] = labelPair(celli, nbri);
        }
    }
    for (label i = 0; couplingWeight > 0 && i < acceptors.size(); ++i)
    {
        const scalar fraction = scalar(poses[i])/nPoses_;
        const label w =
            max(1, label(faceWeight*couplingWeight*fraction + 0.5));
        edgeWeights[nEdges] = w;
        edges[nEdges++] = labelPair(acceptors[i], donors[i]);
        edgeWeights[nEdges] = w;
        edges[nEdges++] = labelPair(donors[i], acceptors[i]);
    }
    edges.setSize(nEdges);
    edgeWeights.setSize(nEdges);
    setRows(edges, edgeWeights, n);
}


// ************************************************************************* //
