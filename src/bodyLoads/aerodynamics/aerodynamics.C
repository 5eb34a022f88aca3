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

#include "aerodynamics.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyLoads
{
    defineTypeNameAndDebug(aerodynamics, 0);
    addToRunTimeSelectionTable(bodyLoad, aerodynamics, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyLoads::aerodynamics::aerodynamics
(
    const objectRegistry& db,
    const RBD::rigidBodyModel& model,
    const dictionary& dict
)
:
    bodyLoad(db, model)
{
    const dictionary& wingsDict = dict.subDict("aerodynamics");
    for (const entry& e : wingsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(wingsDict)
                << e.keyword() << ": an entry of aerodynamics must be a"
                << " wing's dictionary (type, body, ...)"
                << exit(FatalIOError);
        }
        wings_.append(wingAerodynamics::New(e.keyword(), model, e.dict()));
    }
    if (wings_.empty())
    {
        FatalIOErrorInFunction(wingsDict)
            << "no wing: bodyLoad aerodynamics needs at least one entry"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::bodyLoads::aerodynamics::keys()
{
    static const wordList k({"aerodynamics"});
    return k;
}


void Foam::bodyLoads::aerodynamics::checkEntries
(
    const objectRegistry& db,
    const RBD::rigidBodyModel& model,
    const dictionary& dict
)
{
    if (dict.found("aerodynamics", keyType::LITERAL))
    {
        const aerodynamics wings(db, model, dict);
    }
}


void Foam::bodyLoads::aerodynamics::loads
(
    const RBD::rigidBodyModelState& state,
    Field<spatialVector>& fx
) const
{
    model_.forwardDynamicsCorrection(state);

    fx = Zero;
    for (const wingAerodynamics& wing : wings_)
    {
        fx[wing.bodyID()] += wing.load(model_);
    }
}


// ************************************************************************* //
