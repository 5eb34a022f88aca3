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


Description
    octreeInverseDistance: reading and checking the settings of
    oversetInterpolation (choices, ranges, searchBox and its divisions,
    noHoleCut, unknown keys).

\*---------------------------------------------------------------------------*/

#include "octreeInverseDistanceCellCellStencil.H"
#include "FlatOutput.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class EnumType>
EnumType Foam::cellCellStencils::octreeInverseDistance::readChoice
(
    const word& key,
    const Enum<EnumType>& names,
    const EnumType deflt
) const
{
    const word name(dict_.getOrDefault<word>(key, names[deflt]));
    if (!names.found(name))
    {
        FatalIOErrorInFunction(dict_)
            << key << " " << name << " unknown: must be one of "
            << names.sortedToc() << exit(FatalIOError);
    }
    return names[name];
}


void Foam::cellCellStencils::octreeInverseDistance::readSettings()
{
    checkKeys();
    search_ = readChoice("search", searchTypeNames, searchType::cached);
    holeCutting_ =
        readChoice
        (
            "holeCutting", holeCuttingTypeNames, holeCuttingType::incremental
        );
    readNumbers();
    readNoHoleCut();
}


void Foam::cellCellStencils::octreeInverseDistance::readNumbers()
{
    maxWalk_ = dict_.getOrDefault<label>("maxWalk", 16);
    if (maxWalk_ < 0)
    {
        FatalIOErrorInFunction(dict_)
            << "maxWalk " << maxWalk_ << " out of range: must be >= 0"
            << exit(FatalIOError);
    }

    rigidTolerance_ = dict_.getOrDefault<scalar>("rigidTolerance", 1e-6);
    if (rigidTolerance_ <= 0 || rigidTolerance_ >= 1)
    {
        FatalIOErrorInFunction(dict_)
            << "rigidTolerance " << rigidTolerance_
            << " out of range: must be in (0, 1)" << exit(FatalIOError);
    }

    layerRelax_ = dict_.getOrDefault<scalar>("layerRelax", 1);
    if (layerRelax_ < 0 || layerRelax_ > 1)
    {
        FatalIOErrorInFunction(dict_)
            << "layerRelax " << layerRelax_
            << " out of range: must be in [0, 1]" << exit(FatalIOError);
    }

    tolerance_ = dict_.getOrDefault<scalar>("tolerance", 1e-10);
    if (tolerance_ <= 0 || tolerance_ >= 1)
    {
        FatalIOErrorInFunction(dict_)
            << "tolerance " << tolerance_
            << " out of range: must be in (0, 1)" << exit(FatalIOError);
    }

    readSearchBox();

    log_ = dict_.getOrDefault<bool>("log", false);
}


void Foam::cellCellStencils::octreeInverseDistance::readSearchBox()
{
    useSearchBox_ = dict_.readIfPresent("searchBox", searchBox_);
    if
    (
        useSearchBox_
     && (searchBox_.empty() || cmptMin(searchBox_.span()) <= 0)
    )
    {
        FatalIOErrorInFunction(dict_)
            << "searchBox " << searchBox_ << " is empty or flat: must be"
            << " (min) (max) with max > min in every direction (a 2-D"
            << " case too: span the mesh's thickness)" << exit(FatalIOError);
    }

    useDivisions_ = dict_.readIfPresent("searchBoxDivisions", divisions_);
    if (useDivisions_ && cmptMin(divisions_) < 1)
    {
        FatalIOErrorInFunction(dict_)
            << "searchBoxDivisions " << divisions_
            << " out of range: every component must be >= 1"
            << exit(FatalIOError);
    }

    if (Pstream::parRun() && !(useSearchBox_ && useDivisions_))
    {
        Info<< typeName << " : parallel run without searchBox and"
            << " searchBoxDivisions in " << dict_.name() << ": the hole"
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
        FatalIOErrorInFunction(dict_)
            << "searchBoxDivisions " << divisions_ << " out of range: "
            << nVoxels << " voxels, more than a label holds: the product of"
            << " the components must be <= " << labelMax
            << exit(FatalIOError);
    }
}


void Foam::cellCellStencils::octreeInverseDistance::checkKeys() const
{
    for (const word& key : dict_.toc())
    {
        if (!allowedKeys.found(key))
        {
            FatalIOErrorInFunction(dict_)
                << key << " is not a key of method " << typeName
                << " (misspelled?): allowed keys are "
                << flatOutput(allowedKeys) << exit(FatalIOError);
        }
    }
}


void Foam::cellCellStencils::octreeInverseDistance::readNoHoleCut()
{
    noHoleCut_.clear();
    if (dict_.readIfPresent("noHoleCut", noHoleCut_))
    {
        const label nZones = countZones(this->zoneID());
        for (const labelPair& p : noHoleCut_)
        {
            if
            (
                p.first() < 0 || p.first() >= nZones
             || p.second() < 0 || p.second() >= nZones
             || p.first() == p.second()
            )
            {
                FatalIOErrorInFunction(dict_)
                    << "noHoleCut entry " << p << ": a pair (zone cutter) of"
                    << " two different zones, each in [0, " << nZones - 1
                    << "] (the zoneID values)" << exit(FatalIOError);
            }
        }
        if (noHoleCut_.size() && search_ != searchType::cached)
        {
            FatalIOErrorInFunction(dict_)
                << "noHoleCut " << noHoleCut_ << " needs search "
                << searchTypeNames[searchType::cached]
                << " (search " << searchTypeNames[search_]
                << " is the stock update, which cuts every pair)"
                << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
