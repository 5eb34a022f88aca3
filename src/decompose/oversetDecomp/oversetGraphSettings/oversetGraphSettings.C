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

#include "oversetGraphSettings.H"
#include "dictionaryRead.H"
#include "oversetCouplings.H"
#include "dictionaryKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::oversetGraphSettings::library>
Foam::oversetGraphSettings::libraryNames
({
    { library::metis, "metis" },
    { library::scotch, "scotch" },
});


const Foam::wordList Foam::oversetGraphSettings::keys
({
    "couplings", "couplingWeight", "pose", "partitioner", "imbalance",
    "oversetImbalance", "oversetWork", "poseGroups"
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::oversetGraphSettings::checkPoseGroups
(
    const dictionary& coeffs
) const
{
    if (poseGroups_ != coeffs.getOrDefault<scalar>("poseGroups", -1))
    {
        FatalIOErrorInFunction(coeffs)
            << "poseGroups " << coeffs.get<scalar>("poseGroups")
            << ": an integer in [-1, 1000] is allowed" << exit(FatalIOError);
    }
    if
    (
        coeffs.found("poseGroups") && poseGroups_
     && library_ != library::metis
    )
    {
        FatalIOErrorInFunction(coeffs)
            << "poseGroups " << poseGroups_ << " with partitioner "
            << libraryNames[library_] << ": poseGroups is allowed with"
            << " partitioner metis only (scotch balances one weight)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::oversetGraphSettings::oversetGraphSettings
(
    const dictionary& coeffs,
    const word& name
)
:
    couplings_
    (
        coeffs.getOrDefault<fileName>
        (
            "couplings", "constant"/oversetCouplings::typeName
        )
    ),
    couplingWeight_
    (
        readAllowed
        (
            coeffs, "couplingWeight", 1.0, allowed::closed(0.0, 1000.0)
        )
    ),
    pose_(coeffs.getOrDefault<label>("pose", -1)),
    library_
    (
        readChoice(coeffs, "partitioner", libraryNames, library::metis)
    ),
    imbalance_
    (
        readAllowed(coeffs, "imbalance", 0.02, allowed::closed(1e-3, 1.0))
    ),
    oversetImbalance_
    (
        readAllowed
        (
            coeffs, "oversetImbalance", 0.1, allowed::closed(1e-3, 10.0)
        )
    ),
    oversetWork_
    (
        readAllowed
        (
            coeffs, "oversetWork", 1.0, allowed::closed(0.0, 1000.0)
        )
    ),
    poseGroups_
    (
        label
        (
            readAllowed(coeffs, "poseGroups", -1.0, allowed::closed(-1.0, 1e3))
        )
    )
{
    dictionaryKeys(keys).named(name).check(coeffs);
    checkPoseGroups(coeffs);
}


// ************************************************************************* //
