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
    Tests of the cached donor search of the octreeInverseDistance stencil
    (Foam::zoneDonorSearch) against brute force on small meshes:

      - the rigid fit (Kabsch) recovers a known rotation and translation;
        a deformed pose gives a residual of the size of the deformation;
      - a zone that is only nearly rigid (one face plane 1e-7 off): the
        cell found in the reference frame is corrected to the one that
        holds the point in the current mesh (currentCell);
      - on a block of hexahedra with jittered (warped, non-planar) interior
        points, moved rigidly: for random points (some outside) the walk
        from a random / previous / invalid seed, the octree and a brute-force
        loop over the cells of the MOVED mesh give the same cell;
      - degenerate queries: mesh vertices and face centres (ties: any cell
        that contains the point), far outside, maxWalk 0;
      - an empty zone (no cells): no donor, identity fit;
    and the orphan rule of the octreeInverseDistance stencil.  The other
    classes are tested in their own files, linked into the same program
    (flapFoamTest-overset): Test-patchVoxelMap.C,
    Test-patchVoxelExchange.C, Test-cellBins.C, Test-oversetRankReport.C,
    Test-holeFlood.C;
    the small meshes are in oversetTestMeshes.H.

    Every test asserts; the program exits non-zero on failure.

\*---------------------------------------------------------------------------*/

#include "zoneDonorSearch.H"
#include "octreeInverseDistanceCellCellStencil.H"
#include "polyMesh.H"
#include "cellModel.H"
#include "cellShapeList.H"
#include "quaternion.H"
#include "Random.H"
#include "scratchTime.H"
#include "oversetTestMeshes.H"

#include <gtest/gtest.h>

#include <memory>

using namespace Foam;
using namespace oversetTest;

// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(zoneDonorSearch, rigidFitRecoversTransform)
{
    scratchTime time("flapFoamTest-overset", 1, 1);
    const auto mesh0 = hexBlock(time(), "ref", 4, 0.2);
    zoneDonorSearch search(*mesh0, 16);

    const tensor R = someRotation();
    const vector t(0.4, -1.2, 3.0);

    pointField moved(mesh0->points().size());
    forAll(moved, i)
    {
        moved[i] = (R & mesh0->points()[i]) + t;
    }

    const scalar residual = search.fitTransform(moved);
    EXPECT_LT(residual, 1e-12);
    EXPECT_LT(mag(search.R() - R), 1e-12);
    EXPECT_LT(mag(search.t() - t), 1e-12);

    forAll(moved, i)
    {
        EXPECT_LT(mag(search.toReference(moved[i]) - mesh0->points()[i]), 1e-12);
    }

    // Through a point map (reversed order of a larger list)
    pointField all(2*moved.size(), vector(9, 9, 9));
    labelList pointMap(moved.size());
    forAll(moved, i)
    {
        pointMap[i] = all.size() - 1 - i;
        all[pointMap[i]] = moved[i];
    }
    EXPECT_LT(search.fitTransform(all, pointMap), 1e-12);
    EXPECT_LT(mag(search.R() - R), 1e-12);

    // Unmoved: identity exactly
    EXPECT_EQ(search.fitTransform(mesh0->points()), 0);
    EXPECT_TRUE(search.R() == tensor::I);
    EXPECT_TRUE(search.t() == vector::zero);
}


TEST(zoneDonorSearch, rigidFitDetectsDeformation)
{
    scratchTime time("flapFoamTest-overset", 1, 1);
    const auto mesh0 = hexBlock(time(), "ref", 4, 0.2);
    zoneDonorSearch search(*mesh0, 16);

    const tensor R = someRotation();
    pointField moved(mesh0->points().size());
    forAll(moved, i)
    {
        moved[i] = R & mesh0->points()[i];
    }
    moved[7] += vector(0, 0, 1e-3);

    const scalar residual = search.fitTransform(moved);
    EXPECT_GT(residual, 1e-4);
    EXPECT_LT(residual, 1e-3);

    // Wrong number of points: FatalError
    EXPECT_ANY_THROW(search.fitTransform(pointField(3, Zero)));
}


TEST(zoneDonorSearch, donorsEqualBruteForceInMovedMesh)
{
    scratchTime time("flapFoamTest-overset", 1, 1);
    const label n = 6;
    const tensor R = someRotation();
    const vector t(-0.3, 0.7, 0.2);

    const auto mesh0 = hexBlock(time(), "ref", n, 0.3);
    const auto mesh = hexBlock(time(), "moved", n, 0.3, R, t);

    zoneDonorSearch search(*mesh0, 16);
    search.fitTransform(mesh->points());

    Random rnd(42);
    label seed = -1;
    label nInside = 0;
    label nOutside = 0;

    for (label sample = 0; sample < 2000; ++sample)
    {
        // Reference-frame box [-0.2, 1.2]^3, mapped to the moved pose
        const point q0 = 1.4*rnd.sample01<vector>() - 0.2*vector::one;
        const point q = (R & q0) + t;

        label expected = -1;
        for (label celli = 0; celli < mesh->nCells(); ++celli)
        {
            if (mesh->pointInCell(q, celli, polyMesh::CELL_TETS))
            {
                expected = celli;
                break;
            }
        }
        (expected < 0 ? nOutside : nInside)++;

        const point p0 = search.toReference(q);

        // Previous result as seed (walk), random seed, no seed
        const label fromPrev = search.findCell(p0, seed);
        const label fromRandom =
            search.findCell(p0, rnd.position<label>(0, mesh0->nCells() - 1));
        const label fromNone = search.findCell(p0, -1);

        EXPECT_EQ(fromPrev, expected) << "sample " << sample;
        EXPECT_EQ(fromRandom, expected) << "sample " << sample;
        EXPECT_EQ(fromNone, expected) << "sample " << sample;
        EXPECT_EQ(search.findCellOctree(p0), expected);
        EXPECT_EQ(search.findCellBruteForce(p0), expected);

        if (fromPrev >= 0)
        {
            seed = fromPrev;
        }
    }

    // Both kinds of queries occurred, and the walk did work
    EXPECT_GT(nInside, 500);
    EXPECT_GT(nOutside, 100);
    EXPECT_GT(search.nWalk(), 0);
}


TEST(zoneDonorSearch, currentCellOfNearlyRigidZone)
{
    // A zone translated rigidly except one interior face plane (x = 0.5),
    // off by 1e-7 (a displacementLaplacian solved to its tolerance): a
    // point between the rigid and the real plane is in column 2 in the
    // reference frame and in column 1 in the current mesh
    scratchTime time("flapFoamTest-overset", 1, 1);
    const label n = 4;
    const vector t(0.1, 0, 0);
    const auto mesh0 = hexBlock(time(), "ref", n, 0);
    const auto mesh = hexBlock(time(), "moved", n, 0, tensor::I, t);

    pointField pts(mesh->points());
    for (point& p : pts)
    {
        const point p0(p - t);
        const bool interior =
            p0.y() > 0.1 && p0.y() < 0.9 && p0.z() > 0.1 && p0.z() < 0.9;
        if (interior && mag(p0.x() - 0.5) < 1e-9)
        {
            p.x() += 1e-7;
        }
    }
    mesh->movePoints(pts);

    zoneDonorSearch search(*mesh0, 16);
    const scalar residual = search.fitTransform(mesh->points());
    EXPECT_GT(residual, 5e-8);
    EXPECT_LT(residual, 1e-7);

    const labelList cellMap(identity(mesh->nCells()));
    const point q(t + point(0.5 + 5e-8, 0.375, 0.375));
    const label fromReference = search.findCell(search.toReference(q), -1);
    const label expected = search.findCellBruteForce(q - t - point(1e-7, 0, 0));
    ASSERT_GE(fromReference, 0);
    EXPECT_TRUE(mesh->pointInCell(q, expected, polyMesh::CELL_TETS));
    EXPECT_FALSE(mesh->pointInCell(q, fromReference, polyMesh::CELL_TETS));

    search.resetCounters();
    EXPECT_EQ(search.currentCell(*mesh, cellMap, q, fromReference), expected);
    EXPECT_EQ(search.nCorrected(), 1);

    // A point away from the faces keeps its cell; none: -1 stays
    const point r(t + point(0.6, 0.375, 0.375));
    const label cellR = search.findCell(search.toReference(r), -1);
    EXPECT_EQ(search.currentCell(*mesh, cellMap, r, cellR), cellR);
    EXPECT_EQ(search.currentCell(*mesh, cellMap, r, -1), -1);
    EXPECT_EQ(search.nCorrected(), 1);
}


TEST(zoneDonorSearch, degenerateQueries)
{
    scratchTime time("flapFoamTest-overset", 1, 1);
    const auto mesh0 = hexBlock(time(), "ref", 4, 0.25);
    const polyMesh& m = *mesh0;

    // maxWalk 0: octree only; maxWalk 1: the seed cell only
    for (const label maxWalk : {0, 1, 16})
    {
        zoneDonorSearch search(m, maxWalk);

        // Ties (vertices, face centres): a cell that contains the point,
        // found whenever brute force finds one
        DynamicList<point> ties(m.points());
        ties.append(m.faceCentres());
        forAll(ties, i)
        {
            const point& p = ties[i];
            const label brute = search.findCellBruteForce(p);
            const label walked = search.findCell(p, (7*i) % m.nCells());
            const label tree = search.findCellOctree(p);

            if (brute >= 0)
            {
                ASSERT_GE(walked, 0) << "point " << i;
                ASSERT_GE(tree, 0) << "point " << i;
                EXPECT_TRUE(m.pointInCell(p, walked, polyMesh::CELL_TETS));
                EXPECT_TRUE(m.pointInCell(p, tree, polyMesh::CELL_TETS));
            }
        }

        // Cell centres: exactly the cell
        for (label celli = 0; celli < m.nCells(); ++celli)
        {
            const point& c = m.cellCentres()[celli];
            EXPECT_EQ(search.findCell(c, 0), celli);
            EXPECT_EQ(search.findCell(c, celli), celli);
        }

        // Far outside, NaN-free huge values, invalid seeds
        EXPECT_EQ(search.findCell(point(5, 5, 5), 0), -1);
        EXPECT_EQ(search.findCell(point(-1e30, 0, 0), -1), -1);
        EXPECT_EQ(search.findCell(point(0.5, 0.5, 0.5), -7),
            search.findCellBruteForce(point(0.5, 0.5, 0.5)));
        EXPECT_EQ(search.findCell(point(0.5, 0.5, 0.5), m.nCells() + 3),
            search.findCellBruteForce(point(0.5, 0.5, 0.5)));
    }
}


TEST(zoneDonorSearch, emptyZone)
{
    scratchTime time("flapFoamTest-overset", 1, 1);
    polyMesh empty
    (
        IOobject
        (
            "empty",
            time().constant(),
            time(),
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        pointField(),
        faceList(),
        labelList(),
        labelList()
    );

    zoneDonorSearch search(empty, 16);
    EXPECT_EQ(search.findCell(point(0, 0, 0), -1), -1);
    EXPECT_EQ(search.findCell(point(0, 0, 0), 3), -1);
    EXPECT_EQ(search.findCellOctree(point(0, 0, 0)), -1);
    EXPECT_EQ(search.findCellBruteForce(point(0, 0, 0)), -1);
    EXPECT_EQ(search.fitTransform(pointField()), 0);
    EXPECT_TRUE(search.R() == tensor::I);
}


TEST(octreeInverseDistance, orphansAreCellsNeedingADonorWithoutOne)
{
    using stencil = cellCellStencils::octreeInverseDistance;
    const label C = cellCellStencil::CALCULATED;
    const label I = cellCellStencil::INTERPOLATED;
    const label H = cellCellStencil::HOLE;

    // Cells: types after hole marking, previous types, overset-patch cells,
    // donors found
    //   0: overset-patch cell with a donor              -> fine
    //   1: overset-patch cell without a donor           -> orphan
    //   2: overset-patch cell marked hole               -> not an orphan
    //   3: was a hole, calculated now, with a donor     -> fine
    //   4: was a hole, calculated now, without a donor  -> stays a hole
    //      (the stock rule: e.g. inside a solid body), not an orphan
    //   5: was interpolated, calculated now, no donor   -> fine (no need)
    //   6: was a hole, still a hole                     -> not an orphan
    const labelList types({C, C, H, C, C, C, H});
    const labelList prevTypes({C, I, C, H, H, I, H});
    bitSet isOverset(types.size());
    isOverset.set(labelList({0, 1, 2}));
    labelListList donors(types.size());
    donors[0] = labelList(1, 42);
    donors[3] = labelList(1, 7);

    EXPECT_EQ(stencil::findOrphans(types, isOverset, donors), labelList({1}));

    for (label celli = 0; celli < types.size(); ++celli)
    {
        EXPECT_EQ
        (
            stencil::needsDonor
            (
                types[celli], prevTypes[celli], isOverset[celli]
            ),
            celli == 0 || celli == 1 || celli == 3 || celli == 4
        ) << "cell " << celli;
    }

    // Empty input
    EXPECT_TRUE
    (
        stencil::findOrphans(labelList(), bitSet(), labelListList()).empty()
    );
}


// * * * * * * * * * * * * * * * * * * main  * * * * * * * * * * * * * * * * //

int main(int argc, char* argv[])
{
    ::testing::InitGoogleTest(&argc, argv);

    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    return RUN_ALL_TESTS();
}


// ************************************************************************* //
