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

#include "cellBins.H"
#include "patchVoxelMap.H"
#include "zoneDonorSearch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::cellBins::radiusGrow(Foam::sqrt(3.0)*(1 + 1e-6));


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cellBins::binRange
(
    const treeBoundBox& box,
    labelVector& lo,
    labelVector& hi
) const
{
    // Clipped at both ends: a box beyond bb_ (within extent_) meets the
    // edge bins
    const labelVector top(nDivs_ - labelVector::one);
    lo = max
    (
        labelVector::zero,
        min(top, patchVoxelMap::voxel(bb_, nDivs_, box.min()))
    );
    hi = min
    (
        top,
        max(labelVector::zero, patchVoxelMap::voxel(bb_, nDivs_, box.max()))
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cellBins::cellBins()
:
    bb_(treeBoundBox::invertedBox),
    nDivs_(labelVector::one),
    extent_(treeBoundBox::invertedBox),
    start_(2, Zero),
    cells_(),
    nCells_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cellBins::setGrid
(
    const UList<point>& centres,
    const UList<scalar>& radius,
    const settings& s
)
{
    nCells_ = centres.size();
    bb_ = treeBoundBox(treeBoundBox::invertedBox);
    extent_ = treeBoundBox(treeBoundBox::invertedBox);
    forAll(centres, i)
    {
        bb_.add(centres[i]);
        const vector r(vector::uniform(radiusGrow*radius[i]));
        extent_.add(centres[i] - r);
        extent_.add(centres[i] + r);
    }
    if (!nCells_)
    {
        nDivs_ = labelVector::one;
        start_ = labelList(2, Zero);
        cells_.clear();
        return;
    }
    bb_.inflate(1e-6);

    // A flat direction (the centres in a plane, one cell): the bins span
    // the cells' spheres there
    const scalar rMax = radiusGrow*max(radius) + VSMALL;
    for (direction d = 0; d < 3; ++d)
    {
        if (bb_.span()[d] <= 0)
        {
            bb_.min()[d] -= rMax;
            bb_.max()[d] += rMax;
        }
    }

    // About cellsPerBin cells a bin
    const vector span(bb_.span());
    const scalar h = max
    (
        Foam::cbrt(span.x()*span.y()*span.z()/(nCells_/s.cellsPerBin + 1)),
        VSMALL
    );
    for (direction d = 0; d < 3; ++d)
    {
        nDivs_[d] = max(label(1), min(label(span[d]/h), s.maxDivisions));
    }
}


void Foam::cellBins::build
(
    const UList<point>& centres,
    const UList<scalar>& radius,
    const settings& s
)
{
    setGrid(centres, radius, s);
    if (!nCells_)
    {
        return;
    }

    // Compressed rows: count the cells of each bin, then fill
    const label nBins = nDivs_.x()*nDivs_.y()*nDivs_.z();
    start_ = labelList(nBins + 1, Zero);
    labelVector lo, hi;
    for (label pass = 0; pass < 2; ++pass)
    {
        labelList fill;
        if (pass == 1)
        {
            for (label b = 0; b < nBins; ++b)
            {
                start_[b + 1] += start_[b];
            }
            cells_.setSize(start_[nBins]);
            fill = SubList<label>(start_, nBins);
        }
        forAll(centres, i)
        {
            const vector r(vector::uniform(radiusGrow*radius[i]));
            binRange(treeBoundBox(centres[i] - r, centres[i] + r), lo, hi);
            for (label bi = lo.x(); bi <= hi.x(); ++bi)
            {
                for (label bj = lo.y(); bj <= hi.y(); ++bj)
                {
                    for (label bk = lo.z(); bk <= hi.z(); ++bk)
                    {
                        const label b =
                            patchVoxelMap::index(nDivs_, labelVector(bi, bj, bk));
                        if (pass == 0)
                        {
                            ++start_[b + 1];
                        }
                        else
                        {
                            cells_[fill[b]++] = i;
                        }
                    }
                }
            }
        }
    }
}


void Foam::cellBins::collect(const treeBoundBox& box, bitSet& cells) const
{
    if (!nCells_ || !box.overlaps(extent_))
    {
        return;
    }
    labelVector lo, hi;
    binRange(box, lo, hi);
    for (label bi = lo.x(); bi <= hi.x(); ++bi)
    {
        for (label bj = lo.y(); bj <= hi.y(); ++bj)
        {
            for (label bk = lo.z(); bk <= hi.z(); ++bk)
            {
                const label b =
                    patchVoxelMap::index(nDivs_, labelVector(bi, bj, bk));
                for (label k = start_[b]; k < start_[b + 1]; ++k)
                {
                    cells.set(cells_[k]);
                }
            }
        }
    }
}


Foam::labelList Foam::cellBins::holeCandidates
(
    const patchVoxelMap& map,
    const zoneDonorSearch& frame,
    const scalar grow
) const
{
    const labelUList& blockList = map.blockList();
    if (!nCells_ || blockList.empty())
    {
        return labelList();
    }

    bitSet isCandidate(nCells_);
    for (const label blocki : blockList)
    {
        // The block's voxels, grown, in the bins' frame
        treeBoundBox blockBb(map.blockBox(blocki));
        blockBb.min() -= vector::uniform(grow);
        blockBb.max() += vector::uniform(grow);
        collect(frame.toReference(blockBb), isCandidate);
    }
    return isCandidate.toc();
}


// ************************************************************************* //
