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
    Tests of Foam::patchVoxelMap (the voxel map of the octreeInverseDistance
    stencil) against brute force: random face boxes filled into small maps,
    then every voxel, block and query compared with a loop over all voxels
    of the boxes' index ranges; voxels set one by one (the remote path);
    clear() resets every voxel; empty and degenerate maps.

\*---------------------------------------------------------------------------*/

#include "patchVoxelMap.H"
#include "cellCellStencil.H"
#include "Random.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

const unsigned int PATCH = cellCellStencil::patchCellType::PATCH;
const unsigned int OTHER = cellCellStencil::patchCellType::OTHER;

//- Flat voxel index (k fastest, as the stock inverseDistance)
label flat(const labelVector& n, const labelVector& ijk)
{
    return (ijk.x()*n.y() + ijk.y())*n.z() + ijk.z();
}

//- Voxel ijk of a flat index
labelVector ijkOf(const labelVector& n, const label v)
{
    return labelVector(v/(n.y()*n.z()), (v/n.z()) % n.y(), v % n.z());
}

//- A random box of size up to maxSize in [-0.2, 1.2]^3
boundBox randomBox(Random& rnd, const scalar maxSize)
{
    const point lo(-0.2*vector::one + 1.4*rnd.sample01<vector>());
    return boundBox(lo, lo + maxSize*rnd.sample01<vector>());
}

//- Brute force: the voxels (clipped index range of each box) of map
boolList bruteForceVoxels
(
    const patchVoxelMap& map,
    const UList<boundBox>& boxes
)
{
    const labelVector& n = map.nDivs();
    boolList isSet(n.x()*n.y()*n.z(), false);
    for (const boundBox& b : boxes)
    {
        if (!map.bb().overlaps(b))
        {
            continue;
        }
        const labelVector lo(max(labelVector::zero, map.voxel(b.min())));
        const labelVector hi(min(n - labelVector::one, map.voxel(b.max())));
        for (label k = lo.z(); k <= hi.z(); ++k)
        {
            for (label j = lo.y(); j <= hi.y(); ++j)
            {
                for (label i = lo.x(); i <= hi.x(); ++i)
                {
                    isSet[flat(n, labelVector(i, j, k))] = true;
                }
            }
        }
    }
    return isSet;
}

//- Brute force: whether a PATCH voxel lies in [lo, hi] (clipped)
bool anyPatchIn
(
    const patchVoxelMap& map,
    const labelVector& lo,
    const labelVector& hi
)
{
    const labelVector& n = map.nDivs();
    for (label k = max(lo.z(), 0); k <= min(hi.z(), n.z() - 1); ++k)
    {
        for (label j = max(lo.y(), 0); j <= min(hi.y(), n.y() - 1); ++j)
        {
            for (label i = max(lo.x(), 0); i <= min(hi.x(), n.x() - 1); ++i)
            {
                if (map.types().get(flat(n, labelVector(i, j, k))) == PATCH)
                {
                    return true;
                }
            }
        }
    }
    return false;
}

//- The block of voxel ijk
labelVector blockOf(const labelVector& ijk)
{
    return ijk/patchVoxelMap::blockSize;
}

//- Compare the map's PATCH voxels, blocks and queries with brute force
void checkAgainstBruteForce(const patchVoxelMap& map, const boolList& isSet)
{
    const labelVector& n = map.nDivs();
    const labelVector nB(patchVoxelMap::blockDivisions(n));

    labelList patch;
    boolList blockHasPatch(nB.x()*nB.y()*nB.z(), false);
    forAll(isSet, v)
    {
        ASSERT_EQ(map.types().get(v) == PATCH, isSet[v]) << "voxel " << v;
        if (isSet[v])
        {
            patch.append(v);
            const labelVector ijk(ijkOf(n, v));
            blockHasPatch[flat(nB, blockOf(ijk))] = true;
        }
    }
    EXPECT_EQ(map.patchVoxels(), patch);
    EXPECT_EQ(map.noPatch(), patch.empty());

    // Only patch faces: the blocks listed are those holding a PATCH voxel
    labelList blocks(map.blockList());
    Foam::sort(blocks);
    labelList expected;
    forAll(blockHasPatch, b)
    {
        if (blockHasPatch[b])
        {
            expected.append(b);
        }
    }
    EXPECT_EQ(blocks, expected);

    // Random voxel ranges: the block test and the range test never miss a
    // PATCH voxel; the block test is exact at block resolution
    Random rnd(7);
    for (label trial = 0; trial < 200; ++trial)
    {
        labelVector lo, hi;
        for (direction d = 0; d < 3; ++d)
        {
            lo[d] = rnd.position<label>(0, n[d] - 1);
            hi[d] = min(n[d] - 1, lo[d] + rnd.position<label>(0, 3));
        }
        const bool any = anyPatchIn(map, lo, hi);
        if (any)
        {
            EXPECT_TRUE(map.meetsPatchRange(lo, hi));
            EXPECT_TRUE(map.anyPatchBlock(lo, hi));
        }
        const bool anyBlock = anyPatchIn
        (
            map,
            blockOf(lo)*patchVoxelMap::blockSize,
            (blockOf(hi) + labelVector::one)*patchVoxelMap::blockSize
          - labelVector::one
        );
        EXPECT_EQ(map.anyPatchBlock(lo, hi), anyBlock);

        // The stock overlaps test on a box
        const treeBoundBox b(randomBox(rnd, 0.2));
        const labelVector bLo(map.voxel(b.min()));
        const labelVector bHi(map.voxel(b.max()));
        EXPECT_EQ
        (
            map.overlapsPatch(b),
            map.bb().overlaps(b) && anyPatchIn(map, bLo, bHi)
        );
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(patchVoxelMap, patchFacesEqualBruteForce)
{
    for (const labelVector& n : {labelVector(9, 17, 12), labelVector(1, 1, 1), labelVector(24, 1, 5)})
    {
        patchVoxelMap map;
        map.reset(boundBox(point::zero, point(1, 1, 1)), n);
        Random rnd(label(n.x()*100 + n.y()));

        DynamicList<boundBox> boxes;
        for (label i = 0; i < 30; ++i)
        {
            boxes.append(randomBox(rnd, 0.15));
            map.fillPatchFace(boxes.last());
        }
        checkAgainstBruteForce(map, bruteForceVoxels(map, boxes));

        // Overset faces on top: only PATCH voxels they cover change
        DynamicList<boundBox> overset;
        for (label i = 0; i < 10; ++i)
        {
            overset.append(randomBox(rnd, 0.1));
            map.fillOversetFace(overset.last());
        }
        const boolList isPatch(bruteForceVoxels(map, boxes));
        const boolList isOverset(bruteForceVoxels(map, overset));
        forAll(isPatch, v)
        {
            EXPECT_EQ(map.types().get(v) == PATCH, isPatch[v] && !isOverset[v])
                << "voxel " << v;
        }

        // Clear: every voxel OTHER, no PATCH range, no block
        map.clear();
        EXPECT_TRUE(map.allOther());
        EXPECT_TRUE(map.noPatch());
        EXPECT_TRUE(map.blockList().empty());
        EXPECT_TRUE(map.patchVoxels().empty());
        checkAgainstBruteForce(map, boolList(n.x()*n.y()*n.z(), false));
    }
}


TEST(patchVoxelMap, singleVoxelsEqualFilledMap)
{
    // A map filled with face boxes, and its PATCH voxels set one by one
    // into a second map (the remote path): the same voxels, blocks, queries
    const boundBox bb(point(-1, 0, 2), point(2, 0.5, 3));
    const labelVector n(20, 7, 9);
    patchVoxelMap filled;
    filled.reset(bb, n);
    Random rnd(3);
    DynamicList<boundBox> boxes;
    for (label i = 0; i < 12; ++i)
    {
        const point lo
        (
            bb.min() + cmptMultiply(rnd.sample01<vector>(), bb.span())
        );
        boxes.append(boundBox(lo, lo + 0.1*cmptMultiply(rnd.sample01<vector>(), bb.span())));
        filled.fillPatchFace(boxes.last());
    }

    patchVoxelMap single;
    single.reset(bb, n);
    for (const label v : filled.patchVoxels())
    {
        single.setPatchVoxel(v);
    }
    checkAgainstBruteForce(single, bruteForceVoxels(filled, boxes));

    // Reset in the same grid clears; in another grid reallocates
    single.reset(bb, n);
    EXPECT_TRUE(single.allOther());
    EXPECT_TRUE(single.noPatch());
    single.reset(bb, labelVector(3, 4, 5));
    EXPECT_EQ(single.types().size(), 60);
    EXPECT_TRUE(single.allOther());
}


TEST(patchVoxelMap, boxesOfVoxelsAndBlocks)
{
    const boundBox bb(point(0, 0, 0), point(2, 1, 3));
    const labelVector n(19, 8, 17);
    patchVoxelMap map;
    map.reset(bb, n);
    const labelVector nB(patchVoxelMap::blockDivisions(n));
    EXPECT_EQ(nB, labelVector(3, 1, 3));

    for (label v = 0; v < n.x()*n.y()*n.z(); v += 7)
    {
        const treeBoundBox vb(map.voxelBox(v));
        const labelVector ijk(ijkOf(n, v));
        EXPECT_EQ(map.voxel(vb.centre()), ijk);

        // The voxel lies in its block's box
        const label b = flat(nB, blockOf(ijk));
        EXPECT_TRUE(map.blockBox(b).contains(vb.centre()));
    }

    // The last blocks are clipped to the map
    const treeBoundBox last(map.blockBox(nB.x()*nB.y()*nB.z() - 1));
    EXPECT_LE(last.max().x(), bb.max().x() + SMALL);
    EXPECT_LE(last.max().z(), bb.max().z() + SMALL);
}


TEST(patchVoxelMap, patchVoxelsByBlock)
{
    // The PATCH voxels grouped by block: the same voxels, blocks ascending,
    // each voxel in its block, the blocks among the map's PATCH blocks
    const boundBox bb(point(0, 0, 0), point(2, 1, 3));
    const labelVector n(19, 8, 17);
    patchVoxelMap map;
    map.reset(bb, n);
    Random rnd(5);
    for (label i = 0; i < 20; ++i)
    {
        map.fillPatchFace(randomBox(rnd, 0.2));
    }
    const labelList voxels(map.patchVoxels());
    const patchVoxelMap::blockedVoxels bv(map.patchVoxelBlocks());
    ASSERT_GT(bv.blocks.size(), 1);
    ASSERT_EQ(bv.starts.size(), bv.blocks.size() + 1);
    EXPECT_EQ(bv.starts.first(), 0);
    EXPECT_EQ(bv.starts.last(), voxels.size());

    labelList sorted(bv.voxels);
    Foam::sort(sorted);
    EXPECT_EQ(sorted, voxels);

    const labelVector nB(patchVoxelMap::blockDivisions(n));
    const labelHashSet patchBlocks(map.blockList());
    forAll(bv.blocks, i)
    {
        if (i > 0)
        {
            EXPECT_LT(bv.blocks[i - 1], bv.blocks[i]);
        }
        EXPECT_TRUE(patchBlocks.found(bv.blocks[i]));
        for (label j = bv.starts[i]; j < bv.starts[i + 1]; ++j)
        {
            EXPECT_EQ(map.blockOf(bv.voxels[j]), bv.blocks[i]);
            EXPECT_EQ(bv.blocks[i], flat(nB, blockOf(ijkOf(n, bv.voxels[j]))));
        }
    }
}


TEST(patchVoxelMap, emptyAndDegenerate)
{
    // Never reset: no voxels
    patchVoxelMap map;
    EXPECT_FALSE(map.allocated());
    EXPECT_TRUE(map.noPatch());
    EXPECT_TRUE(map.blockList().empty());
    EXPECT_TRUE(map.patchVoxels().empty());
    map.clear();
    EXPECT_TRUE(map.noPatch());

    // Faces outside the map: nothing set
    map.reset(boundBox(point::zero, point::one), labelVector(4, 4, 4));
    EXPECT_TRUE(map.allocated());
    map.fillPatchFace(boundBox(point(2, 2, 2), point(3, 3, 3)));
    map.fillOversetFace(boundBox(point(-3, 0, 0), point(-2, 1, 1)));
    EXPECT_TRUE(map.noPatch());
    EXPECT_TRUE(map.allOther());

    // An overset face where no PATCH voxel is: not filled
    map.fillOversetFace(boundBox(point::zero, point::one));
    EXPECT_TRUE(map.allOther());

    // A face box that is a point
    map.fillPatchFace(boundBox(point(0.3, 0.3, 0.3), point(0.3, 0.3, 0.3)));
    EXPECT_EQ(map.patchVoxels(), labelList({flat(labelVector(4, 4, 4), labelVector(1, 1, 1))}));
    EXPECT_FALSE(map.noPatch());
}


// ************************************************************************* //
