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

#include "multibodyKeys.H"
#include "eABAMotion.H"
#include "dictionaryKeys.H"

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

const Foam::wordList* Foam::RBD::multibodyKeys::keysOf
(
    const HashTable<wordList>& table,
    const dictionary& dict
)
{
    const word type(dict.getOrDefault<word>("type", word::null));
    const auto iter = table.cfind(type);
    return iter.found() ? &iter.val() : nullptr;
}


void Foam::RBD::multibodyKeys::checkJoint
(
    const dictionary& dict,
    const std::string& where
)
{
    const wordList* own = keysOf(jointTypeKeys(), dict);
    if (!own)
    {
        return;
    }

    wordList allowed(1, word("type"));
    allowed.append(*own);
    const word type(dict.get<word>("type"));
    dictionaryKeys(allowed).named(where + " (type " + type + ")").check(dict);

    if (type == "composite")
    {
        // The stock reader: a list of joint dictionaries
        const PtrList<dictionary> joints(dict.lookup("joints"));
        forAll(joints, i)
        {
            checkJoint(joints[i], where + "/joints[" + Foam::name(i) + "]");
        }
    }
}


void Foam::RBD::multibodyKeys::checkBody(const dictionary& dict) const
{
    const wordList* own = keysOf(bodyTypeKeys(), dict);
    if (!own)
    {
        return;
    }

    // The tree: a body joined to a parent by a joint, or merged with one
    wordList allowed({"type", "transform"});
    allowed.append
    (
        dict.found("mergeWith")
      ? wordList({"mergeWith"})
      : wordList({"parent", "joint"})
    );
    allowed.append(*own);

    const std::string where(dictionaryKeys::pathOf(dict));
    dictionaryKeys(allowed)
        .named(where + " (type " + dict.get<word>("type") + ")")
        .alsoAllowing(body_, note_)
        .check(dict);

    if (dict.isDict("joint"))
    {
        checkJoint(dict.subDict("joint"), where + "/joint");
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

const Foam::HashTable<Foam::wordList>&
Foam::RBD::multibodyKeys::bodyTypeKeys()
{
    // The stock constructors' keys (rigidBodyInertia, sphere, cuboid)
    static const HashTable<wordList> k
    ({
        {"rigidBody", wordList({"mass", "centreOfMass", "inertia"})},
        {"sphere", wordList({"mass", "centreOfMass", "radius"})},
        {"cuboid", wordList({"mass", "centreOfMass", "L"})},
        {"masslessBody", wordList()},
        {"jointBody", wordList()}
    });
    return k;
}


const Foam::HashTable<Foam::wordList>&
Foam::RBD::multibodyKeys::jointTypeKeys()
{
    static const HashTable<wordList> k
    ({
        {"Ra", wordList({"axis"})},
        {"Pa", wordList({"axis"})},
        {"composite", wordList({"joints"})},
        {"Rx", wordList()}, {"Ry", wordList()}, {"Rz", wordList()},
        {"Rs", wordList()}, {"Rxyz", wordList()}, {"Ryxz", wordList()},
        {"Rzyx", wordList()}, {"Px", wordList()}, {"Py", wordList()},
        {"Pz", wordList()}, {"Pxyz", wordList()}, {"floating", wordList()},
        {"null", wordList()}
    });
    return k;
}


const Foam::HashTable<Foam::wordList>&
Foam::RBD::multibodyKeys::solverTypeKeys()
{
    // eABASolvers: each type's constructor
    static const HashTable<wordList> k
    ({
        {"Newmark", wordList({"gamma", "beta"})},
        {"CrankNicolson", wordList({"aoc", "voc"})},
        {"symplectic", wordList()}
    });
    return k;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::multibodyKeys::multibodyKeys
(
    const wordList& coeffs,
    const wordList& body,
    const string& note
)
:
    coeffs_(coeffs),
    body_(body),
    note_(note)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::multibodyKeys::check(const dictionary& dict) const
{
    dictionaryKeys(eABAMotion::keys()).alsoAllowing(coeffs_, note_).check(dict);

    const dictionary* solverPtr = dict.findDict("solver", keyType::LITERAL);
    const wordList* solverKeys =
        solverPtr ? keysOf(solverTypeKeys(), *solverPtr) : nullptr;
    if (solverKeys)
    {
        wordList allowed(1, word("type"));
        allowed.append(*solverKeys);
        dictionaryKeys(allowed)
            .named
            (
                dictionaryKeys::pathOf(*solverPtr) + " (type "
              + solverPtr->get<word>("type") + ")"
            )
            .check(*solverPtr);
    }

    const dictionary* bodiesPtr = dict.findDict("bodies", keyType::LITERAL);
    if (bodiesPtr)
    {
        for (const entry& e : *bodiesPtr)
        {
            if (e.isDict())
            {
                checkBody(e.dict());
            }
        }
    }
}


// ************************************************************************* //
