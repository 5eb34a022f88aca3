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

#include "bodyLoad.H"
#include "treeBody.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bodyLoad, 0);
    defineRunTimeSelectionTable(bodyLoad, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyLoad::bodyLoad
(
    const objectRegistry& db,
    const RBD::rigidBodyModel& model
)
:
    db_(db),
    model_(model)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::bodyLoad::keys()
{
    static const wordList k({"bodyLoad", "fluidLoad"});
    return k;
}


Foam::label Foam::bodyLoad::treeBodyID
(
    const RBD::rigidBodyModel& model,
    const word& name,
    const dictionary& bodyDict
)
{
    return Foam::treeBodyID(model, name, bodyDict);
}


// ************************************************************************* //
