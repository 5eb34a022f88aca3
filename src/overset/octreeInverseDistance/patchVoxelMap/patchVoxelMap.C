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

#include "patchVoxelMap.H"
#include "inverseDistanceCellCellStencil.H"

#include <algorithm>
#include <utility>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::label Foam::patchVoxelMap::blockSize(8);


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The stock voxel arithmetic (protected static members of inverseDistance)
struct voxelOps
:
    public Foam::cellCellStencils::inverseDistance
{
    using inverseDistance::index;
    using inverseDistance::index3;
    using inverseDistance::fill;
    using inverseDistance::overlaps;

    voxelOps() = delete;
};

using Foam::cellCellStencil;

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::patchVoxelMap::addPatchRange
(
    const labelVector& lo,
    const labelVector& hi
)
{
    patchMin_ = min(patchMin_, lo);
    patchMax_ = max(patchMax_, hi);

    const labelVector nBlocks(blockDivisions(nDivs_));
    const labelVector top(min(nDivs_ - labelVector::one, hi));
    const labelVector b0(lo/blockSize);
    const labelVector b1(top/blockSize);
    for (label bi = b0.x(); bi <= b1.x(); ++bi)
    {
        for (label bj = b0.y(); bj <= b1.y(); ++bj)
        {
            for (label bk = b0.z(); bk <= b1.z(); ++bk)
            {
                const label blocki =
                    voxelOps::index(nBlocks, labelVector(bi, bj, bk));
                if (blocks_.set(blocki))
                {
                    blockList_.append(blocki);
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::patchVoxelMap::patchVoxelMap()
:
    bb_(),
    fillBb_(),
    nDivs_(Zero),
    types_(),
    blocks_(),
    blockList_(),
    patchMin_(labelVector::uniform(labelMax)),
    patchMax_(labelVector::uniform(-1)),
    patchBoxes_(),
    oversetBoxes_(),
    setVoxels_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelVector Foam::patchVoxelMap::voxel
(
    const boundBox& bb,
    const labelVector& nDivs,
    const point& p
)
{
    return voxelOps::index3(bb, nDivs, p);
}


Foam::label Foam::patchVoxelMap::index
(
    const labelVector& nDivs,
    const labelVector& ijk
)
{
    return voxelOps::index(nDivs, ijk);
}


Foam::labelVector Foam::patchVoxelMap::ijk
(
    const labelVector& nDivs,
    const label v
)
{
    return voxelOps::index3(nDivs, v);
}


Foam::labelVector Foam::patchVoxelMap::blockDivisions
(
    const labelVector& nDivs
)
{
    return labelVector
    (
        (nDivs.x() + blockSize - 1)/blockSize,
        (nDivs.y() + blockSize - 1)/blockSize,
        (nDivs.z() + blockSize - 1)/blockSize
    );
}


Foam::treeBoundBox Foam::patchVoxelMap::rangeBox
(
    const boundBox& bb,
    const labelVector& nDivs,
    const labelVector& lo,
    const labelVector& hi
)
{
    const vector span(bb.span());
    const vector h
    (
        span.x()/nDivs.x(), span.y()/nDivs.y(), span.z()/nDivs.z()
    );
    return treeBoundBox
    (
        bb.min() + vector(lo.x()*h.x(), lo.y()*h.y(), lo.z()*h.z()),
        bb.min() + vector(hi.x()*h.x(), hi.y()*h.y(), hi.z()*h.z())
    );
}


bool Foam::patchVoxelMap::rangesMeet
(
    const labelVector& lo,
    const labelVector& hi,
    const labelVector& pMin,
    const labelVector& pMax,
    const labelVector& nDivs
)
{
    for (direction d = 0; d < 3; ++d)
    {
        if (hi[d] < pMin[d] || lo[d] > min(pMax[d], nDivs[d] - 1))
        {
            return false;
        }
    }
    return true;
}


bool Foam::patchVoxelMap::noPatch() const
{
    return
        patchMin_.x() > patchMax_.x()
     || patchMin_.y() > patchMax_.y()
     || patchMin_.z() > patchMax_.z();
}


Foam::labelVector Foam::patchVoxelMap::voxel(const point& p) const
{
    return voxelOps::index3(bb_, nDivs_, p);
}


bool Foam::patchVoxelMap::meetsPatchRange
(
    const labelVector& lo,
    const labelVector& hi
) const
{
    return rangesMeet(lo, hi, patchMin_, patchMax_, nDivs_);
}


bool Foam::patchVoxelMap::anyPatchBlock
(
    const labelVector& lo,
    const labelVector& hi
) const
{
    const labelVector nBlocks(blockDivisions(nDivs_));
    const labelVector b0(lo/blockSize);
    const labelVector b1(hi/blockSize);
    for (label bi = b0.x(); bi <= b1.x(); ++bi)
    {
        for (label bj = b0.y(); bj <= b1.y(); ++bj)
        {
            for (label bk = b0.z(); bk <= b1.z(); ++bk)
            {
                if (blocks_.get(voxelOps::index(nBlocks, labelVector(bi, bj, bk))))
                {
                    return true;
                }
            }
        }
    }
    return false;
}


bool Foam::patchVoxelMap::overlapsPatch(const treeBoundBox& subBb) const
{
    return voxelOps::overlaps
    (
        bb_, nDivs_, types_, subBb, cellCellStencil::patchCellType::PATCH
    );
}


Foam::treeBoundBox Foam::patchVoxelMap::blockBox(const label blocki) const
{
    const labelVector b(voxelOps::index3(blockDivisions(nDivs_), blocki));
    const labelVector v0(b*blockSize);
    const labelVector v1(min(nDivs_, (b + labelVector::one)*blockSize));
    return rangeBox(bb_, nDivs_, v0, v1);
}


Foam::treeBoundBox Foam::patchVoxelMap::voxelBox(const label v) const
{
    const labelVector ijk(voxelOps::index3(nDivs_, v));
    return rangeBox(bb_, nDivs_, ijk, ijk + labelVector::one);
}


Foam::labelList Foam::patchVoxelMap::patchVoxels() const
{
    // The PATCH voxels lie in the voxel ranges of the proper-patch face
    // boxes (the overset pass may have overwritten some) and among the
    // single voxels
    const labelVector maxIndex(nDivs_ - labelVector::one);
    DynamicList<label> voxels;
    for (const label v : setVoxels_)
    {
        if (types_.get(v) == cellCellStencil::patchCellType::PATCH)
        {
            voxels.append(v);
        }
    }
    for (const boundBox& faceBb : patchBoxes_)
    {
        const labelVector lo(max(labelVector::zero, voxel(faceBb.min())));
        const labelVector hi(min(maxIndex, voxel(faceBb.max())));

        for (label vi = lo.x(); vi <= hi.x(); ++vi)
        {
            for (label vj = lo.y(); vj <= hi.y(); ++vj)
            {
                for (label vk = lo.z(); vk <= hi.z(); ++vk)
                {
                    const label v =
                        voxelOps::index(nDivs_, labelVector(vi, vj, vk));
                    if (types_.get(v) == cellCellStencil::patchCellType::PATCH)
                    {
                        voxels.append(v);
                    }
                }
            }
        }
    }

    labelList result(std::move(voxels));
    Foam::sort(result);
    result.setSize(std::unique(result.begin(), result.end()) - result.begin());
    return result;
}


Foam::label Foam::patchVoxelMap::blockOf(const label v) const
{
    const labelVector b(voxelOps::index3(nDivs_, v)/blockSize);
    return voxelOps::index(blockDivisions(nDivs_), b);
}


Foam::patchVoxelMap::blockedVoxels
Foam::patchVoxelMap::patchVoxelBlocks() const
{
    const labelList voxels(patchVoxels());
    List<std::pair<label, label>> keyed(voxels.size());
    forAll(voxels, i)
    {
        keyed[i] = std::make_pair(blockOf(voxels[i]), voxels[i]);
    }
    std::sort(keyed.begin(), keyed.end());

    blockedVoxels out;
    out.voxels.setSize(keyed.size());
    DynamicList<label> blocks;
    DynamicList<label> starts;
    forAll(keyed, i)
    {
        out.voxels[i] = keyed[i].second;
        if (i == 0 || keyed[i].first != keyed[i - 1].first)
        {
            blocks.append(keyed[i].first);
            starts.append(i);
        }
    }
    starts.append(keyed.size());
    out.blocks.transfer(blocks);
    out.starts.transfer(starts);
    return out;
}


bool Foam::patchVoxelMap::allOther() const
{
    for (label i = 0; i < types_.size(); ++i)
    {
        if (types_.get(i) != cellCellStencil::patchCellType::OTHER)
        {
            return false;
        }
    }
    return true;
}


void Foam::patchVoxelMap::clear()
{
    // Fill with the same boxes, map box and divisions: exactly the voxels
    // set then
    for (const auto* boxes : {&patchBoxes_, &oversetBoxes_})
    {
        for (const boundBox& faceBb : *boxes)
        {
            voxelOps::fill
            (
                types_, fillBb_, nDivs_, faceBb,
                cellCellStencil::patchCellType::OTHER
            );
        }
    }
    for (const label v : setVoxels_)
    {
        types_.set(v, cellCellStencil::patchCellType::OTHER);
    }
    for (const label blocki : blockList_)
    {
        blocks_.unset(blocki);
    }
    patchBoxes_.clear();
    oversetBoxes_.clear();
    setVoxels_.clear();
    blockList_.clear();
    patchMin_ = labelVector::uniform(labelMax);
    patchMax_ = labelVector::uniform(-1);
}


void Foam::patchVoxelMap::reset
(
    const boundBox& bb,
    const labelVector& nDivs
)
{
    clear();

    const label nVoxels = nDivs.x()*nDivs.y()*nDivs.z();
    if (types_.size() != nVoxels || nDivs_ != nDivs)
    {
        const labelVector nB(blockDivisions(nDivs));
        types_ = PackedList<2>(nVoxels, cellCellStencil::patchCellType::OTHER);
        blocks_ = PackedList<1>(nB.x()*nB.y()*nB.z(), 0u);
    }
    bb_ = bb;
    fillBb_ = bb;
    nDivs_ = nDivs;
}


void Foam::patchVoxelMap::moveBox(const boundBox& bb)
{
    bb_ = bb;
}


bool Foam::patchVoxelMap::fillPatchFace(const boundBox& faceBb)
{
    if (!bb_.overlaps(faceBb))
    {
        return false;
    }
    // PATCH range and blocks from the unclipped top voxel (as filled)
    addPatchRange
    (
        max(labelVector::zero, voxel(faceBb.min())),
        voxel(faceBb.max())
    );
    voxelOps::fill
    (
        types_, bb_, nDivs_, faceBb, cellCellStencil::patchCellType::PATCH
    );
    patchBoxes_.append(faceBb);
    return true;
}


void Foam::patchVoxelMap::fillOversetFace(const boundBox& faceBb)
{
    if
    (
        !bb_.overlaps(faceBb)
     || !meetsPatchRange
        (
            max(labelVector::zero, voxel(faceBb.min())),
            voxel(faceBb.max())
        )
    )
    {
        return;
    }
    voxelOps::fill
    (
        types_, bb_, nDivs_, faceBb, cellCellStencil::patchCellType::OVERSET
    );
    oversetBoxes_.append(faceBb);
}


void Foam::patchVoxelMap::setPatchVoxel(const label v)
{
    const labelVector ijk(voxelOps::index3(nDivs_, v));
    types_.set(v, cellCellStencil::patchCellType::PATCH);
    setVoxels_.append(v);
    addPatchRange(ijk, ijk);
}


// ************************************************************************* //
