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

#include "zoneDonorSearch.H"
#include "indexedOctree.H"
#include "treeDataCell.H"
#include "rigidFit.H"
#include "ListOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::zoneDonorSearch::exitFace
(
    const point& p0,
    const label celli
) const
{
    const cell& cFaces = mesh_.cells()[celli];
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& Cf = mesh_.faceCentres();
    const labelList& own = mesh_.faceOwner();

    label best = -1;
    scalar bestDist = 0;

    forAll(cFaces, i)
    {
        const label facei = cFaces[i];
        const scalar magSf = mag(Sf[facei]);
        if (magSf < VSMALL)
        {
            continue;
        }

        // Signed distance outside the face plane, outward from celli
        scalar d = ((p0 - Cf[facei]) & Sf[facei])/magSf;
        if (own[facei] != celli)
        {
            d = -d;
        }

        if (d > bestDist)
        {
            bestDist = d;
            best = facei;
        }
    }

    return best;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::zoneDonorSearch::zoneDonorSearch
(
    const polyMesh& zoneMesh,
    const label maxWalk
)
:
    mesh_(zoneMesh),
    maxWalk_(maxWalk),
    bb_(treeBoundBox::invertedBox),
    nGlobal_(0),
    size_(0),
    c0_(Zero),
    R_(tensor::I),
    c_(Zero),
    nWalk_(0),
    nOctree_(0),
    nOutside_(0),
    nCorrected_(0)
{
    const pointField& pts = mesh_.points();

    // Whole-zone centroid and size: sums over the ranks
    nGlobal_ = returnReduce(pts.size(), sumOp<label>());
    if (nGlobal_)
    {
        c0_ = returnReduce(sum(pts), sumOp<vector>())/scalar(nGlobal_);
        size_ = mag(boundBox(pts, true).span());
    }
    c_ = c0_;

    // Build the cached search structures now, in the reference frame.
    // tetBasePtIs synchronises over the processor patches: every rank
    // calls it, also one that holds no cell of the zone
    (void)mesh_.tetBasePtIs();
    if (mesh_.nCells() && pts.size())
    {
        bb_ = treeBoundBox(pts);
        bb_.inflate(1e-6);
        (void)mesh_.cellTree();
        (void)mesh_.cellCells();
        (void)mesh_.faceAreas();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::zoneDonorSearch::fitTransform(const UList<point>& points)
{
    return fitTransform(points, identity(points.size()));
}


Foam::scalar Foam::zoneDonorSearch::fitTransform
(
    const UList<point>& allPoints,
    const labelUList& pointMap
)
{
    const pointField& pts0 = mesh_.points();
    const UIndirectList<point> points(allPoints, pointMap);

    if (points.size() != pts0.size())
    {
        FatalErrorInFunction
            << "Zone has " << pts0.size() << " reference points but "
            << points.size() << " current points" << abort(FatalError);
    }

    if (nGlobal_ == 0)
    {
        R_ = tensor::I;
        return 0;
    }

    // Static zone (on every rank): identity, exactly
    bool unmoved = true;
    forAll(pts0, i)
    {
        if (points[i] != pts0[i])
        {
            unmoved = false;
            break;
        }
    }
    if (returnReduce(unmoved, andOp<bool>()))
    {
        R_ = tensor::I;
        c_ = c0_;
        return 0;
    }

    // Kabsch: cross-covariance H = sum (x0 - c0)(x - c)^T = U S V^T,
    // R = V diag(1, 1, det(V U^T)) U^T; sums over the ranks
    point c(Zero);
    forAll(points, i)
    {
        c += points[i];
    }
    reduce(c, sumOp<vector>());
    c /= scalar(nGlobal_);

    tensor H(Zero);
    forAll(pts0, i)
    {
        H += (pts0[i] - c0_)*(points[i] - c);
    }
    reduce(H, sumOp<tensor>());

    R_ = rigidFit::kabschRotation(H);
    c_ = c;

    scalar maxResidual = 0;
    forAll(pts0, i)
    {
        maxResidual = max(maxResidual, mag(toCurrent(pts0[i]) - points[i]));
    }

    return returnReduce(maxResidual, maxOp<scalar>());
}


Foam::treeBoundBox Foam::zoneDonorSearch::toReference
(
    const treeBoundBox& bb
) const
{
    if (bb.empty())
    {
        return bb;
    }
    const tmp<pointField> tcorners(bb.points());
    treeBoundBox bb0(treeBoundBox::invertedBox);
    for (const point& p : tcorners())
    {
        bb0.add(toReference(p));
    }
    return bb0;
}


Foam::treeBoundBox Foam::zoneDonorSearch::toCurrent
(
    const treeBoundBox& bb0
) const
{
    if (bb0.empty())
    {
        return bb0;
    }
    const tmp<pointField> tcorners(bb0.points());
    treeBoundBox bb(treeBoundBox::invertedBox);
    for (const point& p0 : tcorners())
    {
        bb.add(toCurrent(p0));
    }
    return bb;
}


Foam::label Foam::zoneDonorSearch::findCellOctree(const point& p0) const
{
    if (!bb_.contains(p0))
    {
        ++nOutside_;
        return -1;
    }

    ++nOctree_;
    return mesh_.cellTree().findInside(p0);
}


Foam::label Foam::zoneDonorSearch::findCell
(
    const point& p0,
    const label seed
) const
{
    if (!bb_.contains(p0))
    {
        ++nOutside_;
        return -1;
    }

    if (seed >= 0 && seed < mesh_.nCells())
    {
        const labelList& own = mesh_.faceOwner();
        const labelList& nei = mesh_.faceNeighbour();

        label celli = seed;
        for (label step = 0; step < maxWalk_; ++step)
        {
            if (mesh_.pointInCell(p0, celli, polyMesh::CELL_TETS))
            {
                ++nWalk_;
                return celli;
            }

            const label facei = exitFace(p0, celli);
            if (facei < 0 || !mesh_.isInternalFace(facei))
            {
                // Warped cell or a boundary of the zone: ask the octree
                break;
            }
            celli = (own[facei] == celli ? nei[facei] : own[facei]);
        }
    }

    ++nOctree_;
    return mesh_.cellTree().findInside(p0);
}


Foam::label Foam::zoneDonorSearch::currentCell
(
    const polyMesh& currentMesh,
    const labelUList& cellMap,
    const point& p,
    const label celli
) const
{
    if
    (
        celli < 0
     || currentMesh.pointInCell(p, cellMap[celli], polyMesh::CELL_TETS)
    )
    {
        return celli;
    }

    for (const label nbr : mesh_.cellCells()[celli])
    {
        if (currentMesh.pointInCell(p, cellMap[nbr], polyMesh::CELL_TETS))
        {
            ++nCorrected_;
            return nbr;
        }
    }
    return celli;
}


Foam::label Foam::zoneDonorSearch::findCellBruteForce(const point& p0) const
{
    for (label celli = 0; celli < mesh_.nCells(); ++celli)
    {
        if (mesh_.pointInCell(p0, celli, polyMesh::CELL_TETS))
        {
            return celli;
        }
    }
    return -1;
}


// ************************************************************************* //
