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
    GoogleTest unit tests of the project's unknown-key check
    (src/common/dictionaryKeys), which every reader calls:
      - editDistance: insertions, deletions, replacements, a swap of two
        neighbours counted 1;
      - nearMiss: a case or plural difference, a letter missing, swapped
        or extra named; nothing for a word with no near key or a short key
        that is a different word (Kq for Kp);
      - check: the message names the dictionary's path in its file, the
        key, the allowed keys and the near miss ("did you mean mass?"), and
        no near miss where there is none.

\*---------------------------------------------------------------------------*/

#include "dictionaryKeys.H"
#include "IFstream.H"
#include "OSspecific.H"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The message of the FatalIOError of checking dict ("" if none)
std::string checkError(const dictionaryKeys& keys, const dictionary& dict)
{
    try
    {
        keys.check(dict);
    }
    catch (const Foam::IOerror& err)
    {
        return err.message();
    }
    return std::string();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * Tests  * * * * * * * * * * * * * * * //

TEST(dictionaryKeys, editDistance)
{
    EXPECT_EQ(dictionaryKeys::editDistance("mass", "mass"), 0);
    EXPECT_EQ(dictionaryKeys::editDistance("mas", "mass"), 1);
    EXPECT_EQ(dictionaryKeys::editDistance("nIters", "nIter"), 1);
    EXPECT_EQ(dictionaryKeys::editDistance("amplitdue", "amplitude"), 1);
    EXPECT_EQ(dictionaryKeys::editDistance("centerOfMass", "centreOfMass"), 1);
    EXPECT_EQ(dictionaryKeys::editDistance("", "abc"), 3);
    EXPECT_EQ(dictionaryKeys::editDistance("kitten", "sitting"), 3);
}


TEST(dictionaryKeys, nearMiss)
{
    const wordList body
    ({
        "type", "parent", "transform", "joint", "mass", "centreOfMass",
        "inertia"
    });
    EXPECT_EQ(dictionaryKeys::nearMiss("mas", body), "mass");
    EXPECT_EQ(dictionaryKeys::nearMiss("Mass", body), "mass");
    EXPECT_EQ(dictionaryKeys::nearMiss("INERTIA", body), "inertia");
    EXPECT_EQ(dictionaryKeys::nearMiss("joints", body), "joint");
    EXPECT_EQ(dictionaryKeys::nearMiss("transfrom", body), "transform");
    EXPECT_EQ(dictionaryKeys::nearMiss("centerOfMass", body), "centreOfMass");
    EXPECT_EQ(dictionaryKeys::nearMiss("tpye", body), "type");
    EXPECT_EQ(dictionaryKeys::nearMiss("radius", body), "");
    EXPECT_EQ(dictionaryKeys::nearMiss("patches", body), "");

    // Short keys: one letter of two is no near miss
    const wordList gains({"Kp", "Ki", "Kd"});
    EXPECT_EQ(dictionaryKeys::nearMiss("Kq", gains), "");
    EXPECT_EQ(dictionaryKeys::nearMiss("kp", gains), "Kp");
    EXPECT_EQ(dictionaryKeys::nearMiss("x", wordList({"g", "q"})), "");
}


TEST(dictionaryKeys, messageNamesPathKeyAllowedAndNearMiss)
{
    const fileName path
    (
        "/tmp/flapFoamTest-dictionaryKeys-" + Foam::name(pid())
    );
    std::ofstream(path.c_str())
        << "coeffs { bodies { wing { type rigidBody; mas 1e-3;"
        << " radius 2; } } }\n";
    IFstream is(path);
    const dictionary file(is);
    rm(path);

    const dictionary& wing =
        file.subDict("coeffs").subDict("bodies").subDict("wing");
    EXPECT_EQ(dictionaryKeys::pathOf(wing), "coeffs/bodies/wing");
    EXPECT_EQ
    (
        dictionaryKeys::pathOf(file),
        "flapFoamTest-dictionaryKeys-" + Foam::name(pid())
    );

    const wordList own({"type", "mass", "radius"});
    const std::string msg(checkError(dictionaryKeys(own), wing));
    EXPECT_NE
    (
        msg.find
        (
            "Unknown key 'mas' in coeffs/bodies/wing; allowed keys are type"
            " mass radius\ndid you mean mass?"
        ),
        std::string::npos
    ) << msg;

    // A key with no near miss: the allowed keys only; named(): the name
    const std::string far
    (
        checkError
        (
            dictionaryKeys(wordList({"type", "mas"})).named("the wing"),
            wing
        )
    );
    EXPECT_NE
    (
        far.find
        (
            "Unknown key 'radius' in the wing; allowed keys are type mas"
        ),
        std::string::npos
    ) << far;
    EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;

    // The keys allowed too: checked and offered as near misses
    const std::string also
    (
        checkError
        (
            dictionaryKeys(wordList({"type"}))
                .alsoAllowing(wordList({"mass", "radius"}), "the load's"),
            wing
        )
    );
    EXPECT_EQ(also.find("Unknown key 'radius'"), std::string::npos) << also;
    EXPECT_NE(also.find("(and the load's: mass radius)\ndid you mean mass?"),
        std::string::npos) << also;
}


// ************************************************************************* //
