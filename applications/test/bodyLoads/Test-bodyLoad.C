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
    Tests of the bodyLoad base class: the run-time selection by the keys
    bodyLoad and fluidLoad (default patchLoad, unknown type a FatalIOError
    listing the valid types) and treeBodyID.

\*---------------------------------------------------------------------------*/

#include "boxLoadsCase.H"

using namespace boxLoadsCase;

// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(bodyLoad, selectsTypeByKeys)
{
    flowCase flow(sqr(dimVelocity), 0);
    const dictionary base(modelDict());
    const RBD::rigidBodyModel model(flow.time(), base);

    const auto selected = [&](const std::string& keys)
    {
        return bodyLoad::New
        (
            flow.mesh(), model, modelDict(keys), "patchLoad"
        )->type();
    };

    // Without bodyLoad: the caller's default
    EXPECT_EQ(selected(""), "patchLoad");
    EXPECT_EQ
    (
        bodyLoad::New(flow.mesh(), model, modelDict(""), "vacuum")->type(),
        "vacuum"
    );
    EXPECT_EQ(selected("bodyLoad patchLoad;"), "patchLoad");
    EXPECT_EQ(selected("bodyLoad vacuum;"), "vacuum");
    EXPECT_EQ(selected("fluidLoad on; bodyLoad vacuum;"), "vacuum");
    EXPECT_EQ(selected("fluidLoad off;"), "vacuum");
    EXPECT_EQ(selected("fluidLoad off; bodyLoad patchLoad;"), "vacuum");
    EXPECT_EQ(selected("fluidLoad off; bodyLoad bogus;"), "vacuum");
}


TEST(Errors, bodyLoadUnknownTypeListsValidTypes)
{
    flowCase flow(sqr(dimVelocity), 0);
    const RBD::rigidBodyModel model(flow.time(), modelDict());

    expectIOError
    (
        [&]()
        {
            bodyLoad::New
            (
                flow.mesh(), model, modelDict("bodyLoad bogus;"), "patchLoad"
            );
        },
        {"bogus", "bodyLoad", "patchLoad", "vacuum"}
    );
}


TEST(bodyLoad, treeBodyID)
{
    flowCase flow(sqr(dimVelocity), 0);
    const dictionary dict
    (
        modelDict
        (
            "bodies { tip { type rigidBody; mergeWith plate; mass 1;"
            " centreOfMass (0 0 0); inertia (0.1 0 0 0.1 0 0.1);"
            " transform (1 0 0 0 1 0 0 0 1) (1 0 0); } }"
        )
    );
    const RBD::rigidBodyModel model(flow.time(), dict);

    for (const word name : {"plate", "arm", "lid"})
    {
        EXPECT_EQ(bodyLoad::treeBodyID(model, name, dict), model.bodyID(name));
    }

    // A merged body: it has no patches of its own
    expectIOError
    (
        [&](){ bodyLoad::treeBodyID(model, "tip", dict); },
        {"tip", "not a body of the tree"}
    );

    // Not a body at all: the same FatalIOError
    expectIOError
    (
        [&](){ bodyLoad::treeBodyID(model, "ghost", dict); },
        {"ghost", "not a body of the tree"}
    );
}


// ************************************************************************* //
