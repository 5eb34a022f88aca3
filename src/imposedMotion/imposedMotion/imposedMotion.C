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
#include "dictionaryKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(imposedMotion, 0);
    defineRunTimeSelectionTable(imposedMotion, dictionary);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::imposedMotion::checkKeys
(
    const word& name,
    const word& type,
    const typeKeys& keys,
    const dictionary& dict
)
{
    wordList allowed(keys.own);
    allowed.append(word("type"));
    allowed.append(keys.jointsKey);

    dictionaryKeys(allowed)
        .named(dictionaryKeys::pathOf(dict) + " (type " + type + ")")
        .alsoAllowing(keys.ignored, "the paper authors' keys, ignored")
        .check(dict);

    wordList ignoredFound;
    for (const entry& e : dict)
    {
        if (keys.ignored.found(e.keyword()))
        {
            ignoredFound.append(e.keyword());
        }
    }

    if (ignoredFound.size())
    {
        IOWarningInFunction(dict)
            << "Entries " << dictionaryKeys::joined(ignoredFound).c_str()
            << " of '" << name << "' (type " << type << ") are keys of"
            << " the paper authors' code that flapFoam does not use: ignored"
            << endl;
    }
}


// * * * * * * * * * * * * * * * * Key Registry  * * * * * * * * * * * * * * //

Foam::imposedMotion::addTypeKeys::addTypeKeys
(
    const word& type,
    const typeKeys& keys
)
{
    typeKeysTable().set(type, keys);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::imposedMotion::imposedMotion
(
    const word& name,
    const dictionary& dict
)
:
    name_(name),
    dict_(dict),
    joints_(1, dict.get<label>("joint"))
{}


Foam::imposedMotion::imposedMotion
(
    const word& name,
    const dictionary& dict,
    const labelList& joints
)
:
    name_(name),
    dict_(dict),
    joints_(joints)
{}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

Foam::HashTable<Foam::imposedMotion::typeKeys>&
Foam::imposedMotion::typeKeysTable()
{
    static HashTable<typeKeys> table;
    return table;
}


const Foam::imposedMotion::typeKeys& Foam::imposedMotion::keysOfType() const
{
    const auto iter = typeKeysTable().cfind(type());
    if (!iter.found())
    {
        FatalErrorInFunction
            << "imposedMotion type " << type() << " registered no keys"
            << " (imposedMotion::addTypeKeys in its .C)" << exit(FatalError);
    }
    return iter.val();
}


Foam::wordList Foam::imposedMotion::keys() const
{
    wordList k(allowedKeys());
    k.append(word("type"));
    k.append(jointsKey());
    return k;
}


void Foam::imposedMotion::write(Ostream& os) const
{
    os.writeEntry("type", type());

    if (jointsKey() == "joint" && joints_.size() == 1)
    {
        os.writeEntry("joint", joints_.first());
    }
    else
    {
        os.writeEntry(jointsKey(), joints_);
    }
}


// ************************************************************************* //
