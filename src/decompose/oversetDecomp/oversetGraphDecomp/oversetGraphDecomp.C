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

#include "oversetGraphDecomp.H"
#include "couplingReport.H"
#include "addToRunTimeSelectionTable.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(oversetGraphDecomp, 0);

    addToRunTimeSelectionTable
    (
        decompositionMethod,
        oversetGraphDecomp,
        dictionary
    );

    addToRunTimeSelectionTable
    (
        decompositionMethod,
        oversetGraphDecomp,
        dictionaryRegion
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::oversetGraphDecomp::notSupported(const string& what) const
{
    FatalErrorInFunction
        << "method " << typeName << " decomposes the undecomposed mesh"
        << " (decomposePar), without constraints; not " << what << "."
        << nl << "To change the number of ranks of a decomposed run:"
        << " reconstructPar and decomposePar, or redistributePar with"
        << " scotch or ptscotch." << exit(FatalError);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::oversetGraphDecomp::oversetGraphDecomp(const dictionary& decompDict)
:
    oversetGraphDecomp(decompDict, word::null)
{}


Foam::oversetGraphDecomp::oversetGraphDecomp
(
    const dictionary& decompDict,
    const word& regionName
)
:
    decompositionMethod(decompDict, regionName),
    settings_
    (
        findCoeffsDict
        (
            typeName + "Coeffs",
            selectionType::EXACT | selectionType::NULL_DICT
        ),
        typeName + "Coeffs"
    ),
    partitioner_(settings_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::oversetGraphDecomp::decompose
(
    const polyMesh& mesh,
    const pointField&,
    const scalarField& cellWeights
) const
{
    if (Pstream::parRun())
    {
        notSupported("a decomposed mesh in parallel");
    }
    oversetCouplings couplings
    (
        mesh.time(), settings_.couplings(), mesh.nCells()
    );
    if (settings_.pose() != -1)
    {
        couplings.keepOnly(settings_.pose());
    }
    const couplingGraph graph
    (
        mesh, couplings, settings_.couplingWeight(), cellWeights
    );
    const labelList decomp(partitioner_.partition(graph, nDomains_));
    Info<< typeName << ": " << nDomains_ << " ranks, " << mesh.nCells()
        << " cells, " << partitioner_.libraryName() << " underneath, ";
    if (settings_.pose() == -1)
    {
        Info<< couplings.nPoses() << " poses";
    }
    else
    {
        Info<< "kept pose " << settings_.pose();
    }
    Info<< " of " << settings_.couplings() << nl;
    couplingReport(mesh, graph, couplings, decomp, nDomains_)
        .write(Info, typeName);
    Info<< endl;
    return decomp;
}


Foam::labelList Foam::oversetGraphDecomp::decompose
(
    const polyMesh&,
    const labelList&,
    const pointField&,
    const scalarField&
) const
{
    notSupported("with decomposition constraints (preserve*, singleProcessor*)");
    return labelList();
}


Foam::labelList Foam::oversetGraphDecomp::decompose
(
    const labelListList&,
    const pointField&,
    const scalarField&
) const
{
    notSupported("an explicit cell connectivity (parallel redistribution)");
    return labelList();
}


// ************************************************************************* //
