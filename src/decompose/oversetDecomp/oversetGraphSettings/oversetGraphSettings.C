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

Foam::scalar Foam::oversetGraphSettings::readInRange
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const scalarMinMax& range
)
{
    const scalar value = dict.getOrDefault<scalar>(key, deflt);
    if (!range.contains(value))
    {
        FatalIOErrorInFunction(dict)
            << key << " " << value << ": a value in [" << range.min()
            << ", " << range.max() << "] is allowed" << exit(FatalIOError);
    }
    return value;
}


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
        readInRange(coeffs, "couplingWeight", 1, scalarMinMax(0, 1000))
    ),
    pose_(coeffs.getOrDefault<label>("pose", -1)),
    library_
    (
        libraryNames.getOrDefault("partitioner", coeffs, library::metis)
    ),
    imbalance_
    (
        readInRange(coeffs, "imbalance", 0.02, scalarMinMax(1e-3, 1))
    ),
    oversetImbalance_
    (
        readInRange
        (
            coeffs, "oversetImbalance", 0.1, scalarMinMax(1e-3, 10)
        )
    ),
    oversetWork_
    (
        readInRange(coeffs, "oversetWork", 1, scalarMinMax(0, 1000))
    ),
    poseGroups_
    (
        label(readInRange(coeffs, "poseGroups", -1, scalarMinMax(-1, 1000)))
    )
{
    dictionaryKeys(keys).named(name).check(coeffs);
    checkPoseGroups(coeffs);
}


// ************************************************************************* //
