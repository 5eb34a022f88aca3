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


Application
    oversetStencils

Description
    Lists the overset stencils that a case's oversetInterpolation/method
    may name: the run-time selection table of cellCellStencil, with the
    stock stencils (liboverset) and the project's (libflapFoamOverset,
    octreeInverseDistance) linked in; a name a line, sorted.  The drone
    cases' Allrun -stencil and the overset bench check their stencils
    against it, so that no script keeps a list of its own.

Usage
    \verbatim
    oversetStencils
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "cellCellStencil.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char* argv[])
{
    argList::addNote
    (
        "The overset stencils of the run-time table (cellCellStencil),"
        " a name a line"
    );
    argList::noBanner();
    argList::noParallel();
    argList::noFunctionObjects();
    argList args(argc, argv);

    for (const word& name : cellCellStencil::meshConstructorTablePtr_->sortedToc())
    {
        Info<< name.c_str() << nl;
    }

    return 0;
}


// ************************************************************************* //
