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
    oversetCouplingsReport

Group
    grpFlapFoamUtilities

Description
    What a decomposition gives each rank of an overset mesh (couplingReport):
    cells, processor faces, overset work, and the donor-acceptor pairs of a
    flapping cycle (constant/oversetCouplings, from oversetMotionCheck
    -couplings) whose donor lands on another rank than its acceptor.  Reads
    any method's cell-to-rank list (decomposePar -cellDist writes
    constant/cellDecomposition), so that every method is measured the same
    way as oversetGraph measures itself.  Serial, on the undecomposed case.

Usage
    \b oversetCouplingsReport [-couplings FILE] [-decomposition FILE]
        [-ranks N] [-pose K]

    Options:
      - \par -couplings FILE (default constant/oversetCouplings)
      - \par -decomposition FILE (default constant/cellDecomposition)
      - \par -ranks N: the number of ranks (default: the largest rank + 1;
        not fewer)
      - \par -pose K: kept pose K of the couplings alone, as if it were the
        only pose (oversetCouplings::keepOnly: no holes); default all poses

    A decomposition that is not a rank >= 0 for each cell of the mesh, or
    a bad -ranks, stops with an error naming the file or the option.

    Output lines start with "oversetCouplingsReport:" (couplingReport's
    format).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "labelIOList.H"
#include "couplingReport.H"
#include "runInputCheck.H"

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// A cell-to-rank list of the mesh: a rank >= 0 for each cell, else
// FatalIOError naming the file
void checkDecomposition(const labelIOList& decomp, const label nCells)
{
    if (decomp.size() != nCells)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, decomp.objectPath())
            << decomp.objectPath().c_str() << " has " << decomp.size()
            << " entries: a rank for each of the " << nCells << " cells of"
            << " the mesh is allowed (decomposePar -cellDist of this case)"
            << exit(FatalIOError);
    }
    if (decomp.size() && min(decomp) < 0)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, decomp.objectPath())
            << "rank " << min(decomp) << " in " << decomp.objectPath().c_str()
            << ": ranks >= 0 are allowed" << exit(FatalIOError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Per-rank cells, processor faces, overset work and remote"
        " donor-acceptor pairs of a decomposition of an overset mesh"
    );
    argList::noParallel();
    argList::addOption("couplings", "FILE", "default constant/oversetCouplings");
    argList::addOption
    (
        "decomposition", "FILE", "default constant/cellDecomposition"
    );
    argList::addOption("ranks", "N", "default: the largest rank + 1");
    argList::addOption("pose", "K", "kept pose K alone (default: all poses)");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const fileName couplingsFile
    (
        args.getOrDefault<fileName>("couplings", "constant/oversetCouplings")
    );
    const fileName decompFile
    (
        args.getOrDefault<fileName>
        (
            "decomposition", "constant/cellDecomposition"
        )
    );
    const labelIOList decomp
    (
        IOobject
        (
            decompFile.isAbsolute() ? decompFile : runTime.path()/decompFile,
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    checkDecomposition(decomp, mesh.nCells());
    const label nUsed = decomp.empty() ? 1 : max(decomp) + 1;
    const label nRanks = runInputCheck::option<label>
    (
        args, "ranks", nUsed, labelMinMax(nUsed, labelMax),
        ("an integer >= " + Foam::name(nUsed) + " (the ranks of "
       + decompFile + ")").c_str()
    );

    const label pose = runInputCheck::option<label>
    (
        args, "pose", -1, labelMinMax(0, labelMax),
        "a kept pose of the couplings, an integer >= 0"
    );

    oversetCouplings couplings(mesh, couplingsFile, mesh.nCells());
    if (pose != -1)
    {
        couplings.keepOnly(pose);
    }
    const couplingGraph graph(mesh, couplings, 1, scalarField());
    Info<< "oversetCouplingsReport: " << nRanks << " ranks, " << mesh.nCells()
        << " cells, " << couplings.nPoses() << " poses of " << couplingsFile
        << ", decomposition " << decompFile;
    if (pose != -1)
    {
        Info<< ", kept pose " << pose;
    }
    Info<< nl;
    couplingReport(mesh, graph, couplings, decomp, nRanks)
        .write(Info, "oversetCouplingsReport");

    Info<< nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
