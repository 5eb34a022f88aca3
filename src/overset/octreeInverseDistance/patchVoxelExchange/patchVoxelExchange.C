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

#include "patchVoxelExchange.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::patchVoxelExchange::patchVoxelExchange()
:
    remote_(),
    nSent_(0),
    nScanned_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelListList Foam::patchVoxelExchange::select
(
    const UList<patchVoxelMap>& local,
    const labelListList& voxels,
    const List<treeBoundBoxList>& tgtBb
)
{
    labelListList send(voxels.size());
    forAll(voxels, zonei)
    {
        if (voxels[zonei].empty() || tgtBb[zonei].empty())
        {
            continue;
        }

        DynamicList<label> sendVoxels;
        nScanned_ += voxels[zonei].size();
        for (const label v : voxels[zonei])
        {
            treeBoundBox voxelBb(local[zonei].voxelBox(v));
            // Round-off of index3 at the voxel faces
            voxelBb.inflate(1e-6);

            for (const treeBoundBox& bb : tgtBb[zonei])
            {
                if (bb.overlaps(voxelBb))
                {
                    sendVoxels.append(v);
                    break;
                }
            }
        }
        send[zonei].transfer(sendVoxels);
    }
    return send;
}


Foam::labelListList Foam::patchVoxelExchange::select
(
    const UList<patchVoxelMap>& local,
    const UList<patchVoxelMap::blockedVoxels>& voxels,
    const List<treeBoundBoxList>& tgtBb
)
{
    // The voxels of the blocks whose box meets a box, then those tested
    // one by one
    labelListList inBlocks(voxels.size());
    forAll(voxels, zonei)
    {
        const patchVoxelMap::blockedVoxels& bv = voxels[zonei];
        if (bv.voxels.empty() || tgtBb[zonei].empty())
        {
            continue;
        }

        DynamicList<label> kept;
        forAll(bv.blocks, i)
        {
            treeBoundBox blockBb(local[zonei].blockBox(bv.blocks[i]));
            // At least each voxel's inflation in select (1e-6 of its span)
            blockBb.inflate(1e-6);

            for (const treeBoundBox& bb : tgtBb[zonei])
            {
                if (bb.overlaps(blockBb))
                {
                    for (label j = bv.starts[i]; j < bv.starts[i + 1]; ++j)
                    {
                        kept.append(bv.voxels[j]);
                    }
                    break;
                }
            }
        }
        inBlocks[zonei].transfer(kept);
    }
    return select(local, inBlocks, tgtBb);
}


void Foam::patchVoxelExchange::clear(const label nZones)
{
    remote_ = List<patchVoxelMap>(nZones);
    nSent_ = 0;
    nScanned_ = 0;
}


void Foam::patchVoxelExchange::exchange
(
    const UList<patchVoxelMap>& local,
    const UList<patchVoxelMap::blockedVoxels>& voxels,
    const List<List<treeBoundBoxList>>& tgtBb
)
{
    const label myProci = Pstream::myProcNo();

    // Clear last step's remote voxels, in this step's grids (the ranks
    // share each zone's grid)
    nSent_ = 0;
    nScanned_ = 0;
    forAll(remote_, zonei)
    {
        remote_[zonei].reset(local[zonei].bb(), local[zonei].nDivs());
    }

    // One pass over this rank's PATCH voxels against the bounding box of
    // every rank's boxes of each zone: only these candidates are tested
    // against each rank's boxes (most voxels, e.g. a far field's, meet no
    // other zone at all)
    List<treeBoundBoxList> anyBb(voxels.size());
    forAll(anyBb, zonei)
    {
        treeBoundBox bb(treeBoundBox::invertedBox);
        forAll(tgtBb, proci)
        {
            if (proci != myProci && tgtBb[proci].size())
            {
                for (const treeBoundBox& b : tgtBb[proci][zonei])
                {
                    bb.add(b);
                }
            }
        }
        if (!bb.empty())
        {
            anyBb[zonei].append(bb);
        }
    }
    const labelListList candidates(select(local, voxels, anyBb));

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != myProci)
        {
            const labelListList send(select(local, candidates, tgtBb[proci]));
            label nSend = 0;
            for (const labelList& v : send)
            {
                nSend += v.size();
            }
            nSent_ += nSend;
            if (nSend)
            {
                UOPstream os(proci, pBufs);
                os << send;
            }
        }
    }

    labelList recvSizes;
    pBufs.finishedSends(recvSizes);

    // Merge the received voxels: the hole test asks whether a cell meets a
    // PATCH voxel of any rank, so one map per zone holds them all
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci == myProci || !recvSizes[proci])
        {
            continue;
        }

        UIPstream is(proci, pBufs);
        const labelListList recv(is);
        forAll(recv, zonei)
        {
            for (const label v : recv[zonei])
            {
                remote_[zonei].setPatchVoxel(v);
            }
        }
    }
}


// ************************************************************************* //
