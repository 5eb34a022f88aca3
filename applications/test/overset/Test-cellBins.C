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
    Tests of Foam::cellBins (the bins of a zone's cells in its own frame)
    and of its hole-candidate search against brute force: random centres
    and radii, every cell whose bins meet a query box is found and no
    other; every cell of a moved mesh whose box meets a grown PATCH block
    of a voxel map is a hole candidate, and every candidate lies within a
    bin of one; empty and degenerate inputs.

\*---------------------------------------------------------------------------*/

#include "cellBins.H"
#include "patchVoxelMap.H"
#include "zoneDonorSearch.H"
#include "scratchTime.H"
#include "oversetTestMeshes.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace oversetTest;

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

//- Brute force: the cells whose bin range meets the box's bin range
bitSet bruteForceCollect
(
    const cellBins& bins,
    const UList<point>& centres,
    const UList<scalar>& radius,
    const treeBoundBox& box
)
{
    bitSet found(centres.size());
    if (!box.overlaps(bins.extent()))
    {
        return found;
    }
    const labelVector top(bins.nDivs() - labelVector::one);
    auto range = [&]
    (
        const point& a,
        const point& b,
        labelVector& lo,
        labelVector& hi
    )
    {
        const labelVector va(patchVoxelMap::voxel(bins.bb(), bins.nDivs(), a));
        const labelVector vb(patchVoxelMap::voxel(bins.bb(), bins.nDivs(), b));
        for (direction d = 0; d < 3; ++d)
        {
            lo[d] = std::max(label(0), std::min(top[d], va[d]));
            hi[d] = std::min(top[d], std::max(label(0), vb[d]));
        }
    };
    labelVector qLo, qHi;
    range(box.min(), box.max(), qLo, qHi);
    forAll(centres, i)
    {
        const vector r(vector::uniform(cellBins::radiusGrow*radius[i]));
        labelVector lo, hi;
        range(centres[i] - r, centres[i] + r, lo, hi);
        bool meets = true;
        for (direction d = 0; d < 3; ++d)
        {
            meets = meets && lo[d] <= qHi[d] && qLo[d] <= hi[d];
        }
        if (meets)
        {
            found.set(i);
        }
    }
    return found;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(cellBins, collectEqualsBruteForce)
{
    Random rnd(11);
    const label n = 500;
    pointField centres(n);
    scalarField radius(n);
    forAll(centres, i)
    {
        centres[i] = cmptMultiply(rnd.sample01<vector>(), vector(2, 1, 0.5));
        radius[i] = 0.05*rnd.sample01<scalar>();
    }

    cellBins::settings coarse;
    coarse.cellsPerBin = 50;
    cellBins::settings capped;
    capped.maxDivisions = 2;

    for (const cellBins::settings& s : {cellBins::settings(), coarse, capped})
    {
        cellBins bins;
        bins.build(centres, radius, s);
        EXPECT_EQ(bins.nCells(), n);
        EXPECT_LE(cmptMax(bins.nDivs()), s.maxDivisions);
        EXPECT_GE(cmptMin(bins.nDivs()), 1);

        for (label trial = 0; trial < 100; ++trial)
        {
            const point lo
            (
                cmptMultiply(rnd.sample01<vector>(), vector(2.4, 1.4, 0.9))
              - vector(0.2, 0.2, 0.2)
            );
            const treeBoundBox box(lo, lo + 0.3*rnd.sample01<vector>());

            bitSet found(n);
            bins.collect(box, found);
            EXPECT_EQ(found, bruteForceCollect(bins, centres, radius, box));

            // Geometric guarantee: every cell whose sphere's box meets the
            // query box is found
            forAll(centres, i)
            {
                const vector r(vector::uniform(radius[i]));
                if (box.overlaps(treeBoundBox(centres[i] - r, centres[i] + r)))
                {
                    EXPECT_TRUE(found.test(i)) << "cell " << i;
                }
            }
        }
    }
}


TEST(cellBins, holeCandidatesEqualBruteForce)
{
    scratchTime time("flapFoamTest-overset", 1, 1);
    const auto mesh0 = hexBlock(time(), "ref", 8, 0.2);
    zoneDonorSearch frame(*mesh0, 16);

    // The zone moved rigidly
    const tensor R = someRotation();
    const vector t(0.3, -0.2, 0.1);
    pointField moved(mesh0->points().size());
    forAll(moved, i)
    {
        moved[i] = (R & mesh0->points()[i]) + t;
    }
    ASSERT_LT(frame.fitTransform(moved), 1e-12);

    // Bounding radius of each cell about its centre (reference pose)
    const pointField& cc0 = mesh0->cellCentres();
    scalarField radius(cc0.size(), Zero);
    forAll(cc0, celli)
    {
        for (const label pointi : mesh0->cellPoints()[celli])
        {
            radius[celli] =
                max(radius[celli], mag(mesh0->points()[pointi] - cc0[celli]));
        }
    }
    cellBins bins;
    bins.build(cc0, radius);

    // A voxel map at the current pose with a few patch faces
    patchVoxelMap map;
    map.reset
    (
        boundBox(point(-1, -1, -1), point(2, 2, 2)), labelVector(96, 96, 96)
    );
    Random rnd(5);
    for (label i = 0; i < 3; ++i)
    {
        const point lo(t + 0.2*rnd.sample01<vector>());
        map.fillPatchFace(boundBox(lo, lo + 0.05*rnd.sample01<vector>()));
    }
    ASSERT_FALSE(map.noPatch());

    const scalar grow = 0.01;
    const labelList candidates(bins.holeCandidates(map, frame, grow));
    const bitSet isCandidate(cc0.size(), candidates);
    EXPECT_EQ(label(isCandidate.count()), candidates.size()) << "sorted, unique";

    // Brute force over the cells of the moved mesh: a cell whose box meets
    // a grown PATCH block is a candidate; a candidate lies within a bin's
    // diagonal of some grown block (in the reference frame)
    const vector binSpan
    (
        cmptDivide(bins.bb().span(), vector(bins.nDivs().x(), bins.nDivs().y(), bins.nDivs().z()))
    );
    const scalar binDiag = mag(binSpan);
    label nMust = 0;
    forAll(cc0, celli)
    {
        boundBox cellBb(boundBox::invertedBox);
        for (const label pointi : mesh0->cellPoints()[celli])
        {
            cellBb.add(moved[pointi]);
        }
        bool must = false;
        bool may = false;
        for (const label blocki : map.blockList())
        {
            treeBoundBox blockBb(map.blockBox(blocki));
            blockBb.min() -= vector::uniform(grow);
            blockBb.max() += vector::uniform(grow);
            must = must || blockBb.overlaps(cellBb);

            treeBoundBox near(frame.toReference(blockBb));
            const vector r
            (
                vector::uniform(cellBins::radiusGrow*radius[celli] + binDiag)
            );
            near.min() -= r;
            near.max() += r;
            may = may || near.contains(cc0[celli]);
        }
        nMust += must;
        if (must)
        {
            EXPECT_TRUE(isCandidate.test(celli)) << "cell " << celli;
        }
        if (isCandidate.test(celli))
        {
            EXPECT_TRUE(may) << "cell " << celli;
        }
    }
    EXPECT_GT(nMust, 0) << "the faces meet the zone";
    EXPECT_LT(candidates.size(), cc0.size()) << "not every cell";
}


TEST(cellBins, emptyAndDegenerate)
{
    // No cells
    cellBins none;
    none.build(pointField(), scalarField());
    EXPECT_EQ(none.nCells(), 0);
    bitSet found;
    none.collect(treeBoundBox(point::zero, point::one), found);
    EXPECT_TRUE(found.empty());

    scratchTime time("flapFoamTest-overset", 1, 1);
    const auto mesh0 = hexBlock(time(), "ref", 2, 0);
    zoneDonorSearch frame(*mesh0, 16);
    patchVoxelMap map;
    map.reset(boundBox(point::zero, point::one), labelVector(4, 4, 4));
    map.fillPatchFace(boundBox(point::zero, point::one));
    EXPECT_TRUE(none.holeCandidates(map, frame, 0).empty());

    // One cell (a box of zero size): found by a box around it, not by one
    // far away
    cellBins one;
    one.build(pointField(1, point(1, 2, 3)), scalarField(1, 0.1));
    EXPECT_EQ(one.nDivs(), labelVector::one);
    bitSet hit(1);
    one.collect(treeBoundBox(point(1.05, 2, 3), point(1.2, 2.1, 3.1)), hit);
    EXPECT_TRUE(hit.test(0));
    bitSet miss(1);
    one.collect(treeBoundBox(point(5, 5, 5), point(6, 6, 6)), miss);
    EXPECT_FALSE(miss.test(0));

    // Cells in a plane (a flat box of centres)
    pointField flat(3);
    flat[0] = point(0, 0, 0);
    flat[1] = point(1, 0, 0);
    flat[2] = point(0, 1, 0);
    cellBins plane;
    plane.build(flat, scalarField(3, 0.2));
    bitSet inPlane(3);
    plane.collect(treeBoundBox(point(0.9, -0.1, 0.1), point(1.1, 0.1, 0.15)), inPlane);
    EXPECT_TRUE(inPlane.test(1));

    // A map without PATCH voxels: no candidate
    patchVoxelMap empty;
    empty.reset(boundBox(point::zero, point::one), labelVector(4, 4, 4));
    cellBins bins;
    bins.build(mesh0->cellCentres(), scalarField(mesh0->nCells(), 0.5));
    EXPECT_TRUE(bins.holeCandidates(empty, frame, 0).empty());
    EXPECT_EQ(bins.holeCandidates(map, frame, 0).size(), mesh0->nCells());
}


// ************************************************************************* //
