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

#include "octreeStencilSettings.H"
#include "dictionaryRead.H"
#include "Pstream.H"
#include "dictionaryKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum
<
    Foam::octreeStencilSettings::searchType
>
Foam::octreeStencilSettings::searchTypeNames
({
    { searchType::cached, "cached" },
    { searchType::stock, "stock" },
});

const Foam::Enum
<
    Foam::octreeStencilSettings::holeCuttingType
>
Foam::octreeStencilSettings::holeCuttingTypeNames
({
    { holeCuttingType::incremental, "incremental" },
    { holeCuttingType::full, "full" },
});

const Foam::wordList
Foam::octreeStencilSettings::allowedKeys
({
    "method", "search", "holeCutting", "noHoleCut", "maxWalk",
    "rigidTolerance", "layerRelax", "tolerance", "searchBox",
    "searchBoxFollows", "searchBoxDivisions", "log"
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::octreeStencilSettings::readNumbers(const dictionary& dict)
{
    maxWalk_ =
        readAllowed<label>(dict, "maxWalk", 16, allowed::atLeast<label>(0));
    rigidTolerance_ =
        readAllowed(dict, "rigidTolerance", 1e-6, allowed::open(0.0, 1.0));
    layerRelax_ =
        readAllowed(dict, "layerRelax", 1.0, allowed::closed(0.0, 1.0));
    tolerance_ =
        readAllowed(dict, "tolerance", 1e-10, allowed::open(0.0, 1.0));
    log_ = dict.getOrDefault<bool>("log", false);
}


void Foam::octreeStencilSettings::readSearchBox
(
    const dictionary& dict,
    const word& typeName,
    const label nZones
)
{
    useSearchBox_ = dict.readIfPresent("searchBox", searchBox_);
    if
    (
        useSearchBox_
     && (searchBox_.empty() || cmptMin(searchBox_.span()) <= 0)
    )
    {
        FatalIOErrorInFunction(dict)
            << "searchBox " << searchBox_ << " is empty or flat: must be"
            << " (min) (max) with max > min in every direction (a 2-D"
            << " case too: span the mesh's thickness)" << exit(FatalIOError);
    }

    // A zone, or none (the box fixed in space, as without the key)
    searchBoxFollows_ = -1;
    if (dict.found("searchBoxFollows"))
    {
        ITstream& is = dict.lookup("searchBoxFollows");
        const token t(is);
        const bool none = t.isWord() && t.wordToken() == "none";
        if (t.isLabel())
        {
            searchBoxFollows_ = t.labelToken();
        }
        if
        (
            !none
         && (
                !t.isLabel() || !useSearchBox_ || searchBoxFollows_ < 0
             || searchBoxFollows_ >= nZones
            )
        )
        {
            FatalIOErrorInFunction(dict)
                << "searchBoxFollows " << t << ": must be a zone in [0, "
                << nZones - 1 << "] (the zoneID values), with a searchBox"
                << (useSearchBox_ ? "" : " (none given)") << ", or none"
                << exit(FatalIOError);
        }
    }
    if (searchBoxFollows_ >= 0 && search_ != searchType::cached)
    {
        FatalIOErrorInFunction(dict)
            << "searchBoxFollows " << searchBoxFollows_ << " needs search "
            << searchTypeNames[searchType::cached] << " (search "
            << searchTypeNames[search_] << " is the stock update, whose box"
            << " is fixed)" << exit(FatalIOError);
    }

    useDivisions_ = dict.readIfPresent("searchBoxDivisions", divisions_);
    if (useDivisions_ && cmptMin(divisions_) < 1)
    {
        FatalIOErrorInFunction(dict)
            << "searchBoxDivisions " << divisions_
            << " out of range: every component must be >= 1"
            << exit(FatalIOError);
    }

    if (Pstream::parRun() && !(useSearchBox_ && useDivisions_))
    {
        Info<< typeName << " : parallel run without searchBox and"
            << " searchBoxDivisions in " << dict.name() << ": the hole"
            << " test's voxels span each zone's whole box, divisions from"
            << " the whole mesh's cell count (the serial run's grid); the"
            << " stock inverseDistance takes each rank's own box and cells,"
            << " so its holes depend on the decomposition and can differ"
            << " from these by a voxel near walls.  Give searchBox and"
            << " searchBoxDivisions for one grid in both" << endl;
    }

    // The voxel index must fit in a label
    const scalar nVoxels =
        scalar(divisions_.x())*scalar(divisions_.y())*scalar(divisions_.z());
    if (useDivisions_ && nVoxels > scalar(labelMax))
    {
        FatalIOErrorInFunction(dict)
            << "searchBoxDivisions " << divisions_ << " out of range: "
            << nVoxels << " voxels, more than a label holds: the product of"
            << " the components must be <= " << labelMax
            << exit(FatalIOError);
    }
}


void Foam::octreeStencilSettings::checkKeys
(
    const dictionary& dict,
    const word& typeName
)
{
    dictionaryKeys(allowedKeys).named("method " + typeName).check(dict);
}


void Foam::octreeStencilSettings::readNoHoleCut
(
    const dictionary& dict,
    const label nZones
)
{
    noHoleCut_.clear();
    if (dict.readIfPresent("noHoleCut", noHoleCut_))
    {
        for (const labelPair& p : noHoleCut_)
        {
            if
            (
                p.first() < 0 || p.first() >= nZones
             || p.second() < 0 || p.second() >= nZones
             || p.first() == p.second()
            )
            {
                FatalIOErrorInFunction(dict)
                    << "noHoleCut entry " << p << ": a pair (zone cutter) of"
                    << " two different zones, each in [0, " << nZones - 1
                    << "] (the zoneID values)" << exit(FatalIOError);
            }
        }
        if (noHoleCut_.size() && search_ != searchType::cached)
        {
            FatalIOErrorInFunction(dict)
                << "noHoleCut " << noHoleCut_ << " needs search "
                << searchTypeNames[searchType::cached]
                << " (search " << searchTypeNames[search_]
                << " is the stock update, which cuts every pair)"
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::octreeStencilSettings::octreeStencilSettings
(
    const dictionary& dict,
    const word& typeName,
    const label nZones
)
:
    search_(searchType::cached),
    holeCutting_(holeCuttingType::incremental),
    maxWalk_(16),
    rigidTolerance_(1e-6),
    layerRelax_(1),
    tolerance_(1e-10),
    useSearchBox_(false),
    searchBox_(),
    searchBoxFollows_(-1),
    useDivisions_(false),
    divisions_(Zero),
    noHoleCut_(),
    log_(false)
{
    checkKeys(dict, typeName);
    search_ = readChoice(dict, "search", searchTypeNames, searchType::cached);
    holeCutting_ =
        readChoice
        (
            dict, "holeCutting", holeCuttingTypeNames,
            holeCuttingType::incremental
        );
    readNumbers(dict);
    readSearchBox(dict, typeName, nZones);
    readNoHoleCut(dict, nZones);
}


// ************************************************************************* //
