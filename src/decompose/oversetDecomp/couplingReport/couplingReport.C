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

#include "couplingReport.H"
#include "HashSet.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- max/mean of a per-rank list (1 when all are zero)
scalar imbalance(const scalarList& perRank)
{
    const scalar mean = sum(perRank)/max(1, perRank.size());
    return mean > 0 ? max(perRank)/mean : 1;
}

//- A value rounded to an integer, for the table
label rounded(const scalar x)
{
    return label(x + 0.5);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::couplingReport::countCells
(
    const polyMesh& mesh,
    const couplingGraph& graph,
    const oversetCouplings& couplings,
    const labelUList& decomp
)
{
    const scalar nPoses = couplings.nPoses();
    forAll(decomp, celli)
    {
        const label rank = decomp[celli];
        cells_[rank] += 1;
        weight_[rank] += graph.cellWeight()[celli];
        work_[rank] += graph.oversetWork()[celli]/nPoses;
        acceptors_[rank] += couplings.acceptorPoses()[celli]/nPoses;
    }
    for (label facei = 0; facei < mesh.nInternalFaces(); ++facei)
    {
        const label own = decomp[mesh.faceOwner()[facei]];
        const label nei = decomp[mesh.faceNeighbour()[facei]];
        if (own != nei)
        {
            procFaces_[own] += 1;
            procFaces_[nei] += 1;
        }
    }
}


void Foam::couplingReport::countPairs
(
    const oversetCouplings& couplings,
    const labelUList& decomp
)
{
    const scalar nPoses = couplings.nPoses();
    forAll(couplings.acceptors(), i)
    {
        const label rank = decomp[couplings.acceptors()[i]];
        const scalar perPose = couplings.poses()[i]/nPoses;
        pairs_[rank] += perPose;
        if (decomp[couplings.donors()[i]] != rank)
        {
            remote_[rank] += perPose;
        }
    }
}


void Foam::couplingReport::countSamples
(
    const oversetCouplings& couplings,
    const labelUList& decomp
)
{
    const labelList& poseStart = couplings.samplePoseStart();
    const labelList& acceptors = couplings.sampleAcceptors();
    const labelList& donorStart = couplings.sampleDonorStart();
    const labelList& donors = couplings.sampleDonors();
    const scalar perSample = 1.0/max(1, couplings.nSamples());
    for (label sample = 0; sample < couplings.nSamples(); ++sample)
    {
        // (rank, donor cell) and (rank, donor's rank) of the pose: each
        // remote donor cell and each rank it comes from counted once
        HashSet<labelPair, Hash<labelPair>> received;
        HashSet<labelPair, Hash<labelPair>> fromRanks;
        for (label i = poseStart[sample]; i < poseStart[sample + 1]; ++i)
        {
            const label rank = decomp[acceptors[i]];
            sampled_[rank] += perSample;
            label nRemote = 0;
            for (label j = donorStart[i]; j < donorStart[i + 1]; ++j)
            {
                if (decomp[donors[j]] != rank)
                {
                    ++nRemote;
                    if (received.insert(labelPair(rank, donors[j])))
                    {
                        remoteDonors_[rank] += perSample;
                    }
                    if (fromRanks.insert(labelPair(rank, decomp[donors[j]])))
                    {
                        donorRanks_[rank] += perSample;
                    }
                }
            }
            if (nRemote)
            {
                remoteAcceptors_[rank] += perSample;
            }
            if (nRemote && nRemote == donorStart[i + 1] - donorStart[i])
            {
                allRemoteAcceptors_[rank] += perSample;
            }
        }
    }
}


void Foam::couplingReport::countWorkAtPose
(
    const couplingGraph& graph,
    const labelUList& decomp
)
{
    const labelListList& poseWork = graph.poseWork();
    for (const labelList& cellWork : poseWork)
    {
        scalarList rankWork(cells_.size(), Zero);
        forAll(decomp, celli)
        {
            rankWork[decomp[celli]] += cellWork[celli];
        }
        workAtPose_ += imbalance(rankWork)/poseWork.size();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingReport::couplingReport
(
    const polyMesh& mesh,
    const couplingGraph& graph,
    const oversetCouplings& couplings,
    const labelUList& decomp,
    const label nRanks
)
:
    cells_(nRanks, Zero),
    weight_(nRanks, Zero),
    procFaces_(nRanks, Zero),
    work_(nRanks, Zero),
    acceptors_(nRanks, Zero),
    pairs_(nRanks, Zero),
    remote_(nRanks, Zero),
    sampled_(nRanks, Zero),
    remoteAcceptors_(nRanks, Zero),
    allRemoteAcceptors_(nRanks, Zero),
    remoteDonors_(nRanks, Zero),
    donorRanks_(nRanks, Zero),
    workAtPose_(graph.poseWork().empty() ? 1 : 0)
{
    if (decomp.size() != mesh.nCells() || min(decomp) < 0)
    {
        FatalErrorInFunction
            << "a decomposition of " << decomp.size() << " cells into ranks"
            << " from " << min(decomp) << " to " << max(decomp)
            << ": one rank in [0, " << nRanks - 1 << "] per cell of the mesh"
            << " (" << mesh.nCells() << ") is allowed" << exit(FatalError);
    }
    if (max(decomp) >= nRanks)
    {
        FatalErrorInFunction
            << "rank " << max(decomp) << " in a decomposition into "
            << nRanks << " ranks" << exit(FatalError);
    }
    countCells(mesh, graph, couplings, decomp);
    countPairs(couplings, decomp);
    countSamples(couplings, decomp);
    countWorkAtPose(graph, decomp);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::couplingReport::remoteAcceptorShare() const
{
    const scalar all = sum(sampled_);
    return all > 0 ? sum(remoteAcceptors_)/all : 0;
}


Foam::scalar Foam::couplingReport::allRemoteAcceptorShare() const
{
    const scalar all = sum(sampled_);
    return all > 0 ? sum(allRemoteAcceptors_)/all : 0;
}


Foam::scalar Foam::couplingReport::remotePairShare() const
{
    const scalar allPairs = sum(pairs_);
    return allPairs > 0 ? sum(remote_)/allPairs : 0;
}


void Foam::couplingReport::write(Ostream& os, const word& prefix) const
{
    const List<const scalarList*> columns
    ({
        &cells_, &weight_, &work_, &procFaces_, &acceptors_, &pairs_,
        &remote_, &sampled_, &remoteAcceptors_, &allRemoteAcceptors_,
        &remoteDonors_, &donorRanks_
    });
    os  << prefix << ": rank cells weight oversetWork processorFaces"
        << " acceptors pairs remotePairs sampledAcceptors remoteAcceptors"
        << " allRemoteAcceptors remoteDonors donorRanks" << nl;
    forAll(cells_, rank)
    {
        os  << prefix << ": " << rank;
        for (const scalarList* column : columns)
        {
            os  << ' ' << rounded((*column)[rank]);
        }
        os  << nl;
    }
    os  << prefix << ": total";
    for (const scalarList* column : columns)
    {
        os  << ' ' << rounded(sum(*column));
    }
    os  << nl << prefix << ": imbalance cells " << imbalance(cells_)
        << " weight " << imbalance(weight_) << " oversetWork "
        << imbalance(work_) << " remotePairShare " << remotePairShare()
        << " remoteAcceptorShare " << remoteAcceptorShare()
        << " allRemoteAcceptorShare " << allRemoteAcceptorShare()
        << " oversetWorkAtPose " << workAtPose_ << nl;
}


// ************************************************************************* //
