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

Foam::label Foam::bodyLoad::treeBodyID
(
    const RBD::rigidBodyModel& model,
    const word& name,
    const dictionary& bodyDict
)
{
    // The tree's bodies have the IDs 0 .. nBodies-1 (merged bodies negative
    // ones): look the name up among them, so that an unknown name gets the
    // same FatalIOError as a merged one (model.bodyID fails without naming
    // the dictionary)
    label bodyID = -1;
    for (label bi = 0; bi < model.nBodies() && bodyID < 0; ++bi)
    {
        if (model.name(bi) == name)
        {
            bodyID = bi;
        }
    }

    if (bodyID < 0)
    {
        FatalIOErrorInFunction(bodyDict)
            << "body " << name << " cannot carry patches, a cellZone or a wing:"
            << " it is not a body of the tree (unknown, or merged: merged"
            << " bodies move with their master)" << exit(FatalIOError);
    }

    return bodyID;
}


// ************************************************************************* //
