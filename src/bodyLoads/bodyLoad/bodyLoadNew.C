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
#include "Switch.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bodyLoad> Foam::bodyLoad::New
(
    const objectRegistry& db,
    const RBD::rigidBodyModel& model,
    const dictionary& dict,
    const word& defaultType
)
{
    // fluidLoad off: the bodies in vacuum, whatever the type
    const word loadType
    (
        dict.getOrDefault<Switch>("fluidLoad", true)
      ? dict.getOrDefault<word>("bodyLoad", defaultType)
      : word("vacuum")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(loadType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "bodyLoad",
            loadType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<bodyLoad>(cstrIter()(db, model, dict));
}


// ************************************************************************* //
