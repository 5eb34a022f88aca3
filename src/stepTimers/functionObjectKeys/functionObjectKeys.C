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

#include "functionObjectKeys.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Global Data * * * * * * * * * * * * * * * //

const Foam::wordList Foam::functionObjectKeys::standard
({
    "type", "libs", "enabled", "log", "region", "subRegion",
    "executeControl", "executeInterval", "writeControl", "writeInterval",
    "outputControl", "outputInterval", "timeStart", "timeEnd",
    "triggerStart", "triggerEnd", "controlMode", "deltaTCoeff",
    "nStepsToStartTimeChange"
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The words on one line, space separated
std::string joined(const Foam::wordList& words)
{
    std::string s;
    for (const Foam::word& w : words)
    {
        s += (s.empty() ? "" : " ") + w;
    }
    return s;
}


//- FatalIOError naming the first key of dict not in allowed nor in
//- standard (if any), listing them
void checkKeys
(
    const Foam::dictionary& dict,
    const Foam::wordList& allowed,
    const Foam::wordList& standard
)
{
    for (const Foam::word& key : dict.toc())
    {
        if (!allowed.found(key) && !standard.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown key '" << key << "' in " << dict.dictName()
                << "; allowed: " << joined(allowed).c_str();
            if (standard.size())
            {
                Foam::FatalIOError
                    << " (and those of every function object: "
                    << joined(standard).c_str() << ")";
            }
            Foam::FatalIOError << Foam::exit(Foam::FatalIOError);
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::functionObjectKeys::checkOnly
(
    const dictionary& dict,
    const wordList& allowed
)
{
    checkKeys(dict, allowed, wordList());
}


void Foam::functionObjectKeys::check
(
    const dictionary& dict,
    const wordList& own
)
{
    checkKeys(dict, own, standard);
}


// ************************************************************************* //
