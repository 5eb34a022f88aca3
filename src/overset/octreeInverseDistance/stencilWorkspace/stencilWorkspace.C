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

#include "stencilWorkspace.H"
#include "cellCellStencil.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stencilWorkspace::stencilWorkspace()
:
    incremental(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::stencilWorkspace::reset(const label nCells, const label nZones)
{
    zoneBb.setSize(nZones);
    for (treeBoundBoxList& bbs : zoneBb)
    {
        bbs.setSize(1);
    }
    patchDivs.setSize(nZones);

    patchTypes.setSize(nCells);
    patchTypes = cellCellStencil::patchCellType::OTHER;
    isOversetPatchCell.reset();
    isOversetPatchCell.resize(nCells);

    cellTypes.setSize(nCells);
    cellTypes = cellCellStencil::CALCULATED;

    stencil.setSize(nCells);
    for (labelList& donors : stencil)
    {
        donors.clear();
    }
    donorZone.setSize(nCells);
    donorZone = -1;

    weight.setSize(nCells);
    weight = Zero;

    queried.reset();
    queried.resize(nCells);

    orphans.clear();
    interpolated.clear();

    globalCells.reset(nCells);
}


// ************************************************************************* //
