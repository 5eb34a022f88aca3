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

#include "motionRecord.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(motionRecord, 0);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::motionRecord::motionRecord
(
    const objectRegistry& db,
    const eABAMotion& model,
    const Field<spatialVector>& loads,
    const wordList& bodies,
    const bool freshStart
)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            db.time().timeName(),
            db,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            true
        )
    ),
    model_(model),
    loads_(loads),
    bodies_(bodies),
    bodyIDs_(bodies.size()),
    freshStart_(freshStart)
{
    forAll(bodies_, i)
    {
        bodyIDs_[i] = model_.bodyID(bodies_[i]);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::RBD::motionRecord::centreOfMass
(
    const spatialTransform& X0,
    const label bodyID
) const
{
    // X0 maps global to body coordinates: its inverse places the body's
    // centre of mass in the global frame
    return X0.inv().transformPoint(model_.I(bodyID).c());
}


// ************************************************************************* //
