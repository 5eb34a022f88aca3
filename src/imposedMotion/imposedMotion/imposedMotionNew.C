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

#include "imposedMotion.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::imposedMotion> Foam::imposedMotion::New
(
    const word& name,
    const dictionary& dict
)
{
    const word motionType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(motionType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "imposedMotion",
            motionType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    // The keys first: the type's constructor stops at a missing key
    const auto keysIter = typeKeysTable().cfind(motionType);
    if (keysIter.found())
    {
        if (keysIter.val().checkFirst)
        {
            keysIter.val().checkFirst(dict);
        }
        checkKeys(name, motionType, keysIter.val(), dict);
    }

    return autoPtr<imposedMotion>(cstrIter()(name, dict));
}


// ************************************************************************* //
