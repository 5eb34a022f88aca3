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
    flapFoamTest-controllers: the Usage tables of the controllers' headers
    against the keys each class allows (usageKeys.H): controlTerm,
    controlLoop, and PID (flightController's keys and its own).

\*---------------------------------------------------------------------------*/

#include "rigidBodyTests.H"
#include "usageKeys.H"
#include "flightController.H"
#include "controlLoop.H"

// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(usageKeys, controlTerm)
{
    expectUsageKeys
    (
        usageKeys({"controllers/controlTerm/controlTerm.H"}),
        controlTerm::keys()
    );
}


TEST(usageKeys, controlLoop)
{
    expectUsageKeys
    (
        usageKeys({"controllers/controlLoop/controlLoop.H"}),
        controlLoop::keys()
    );
}


TEST(usageKeys, PID)
{
    dictionary dict(readTestModel("restart"));
    dict.add
    (
        "controller",
        dictFromString
        (
            "type PID; update rate; rate 50;"
            " loops { lift { entry shoulder; parameter amplitude;"
            " saturation tanh; min 0.5; max 1.5; terms { z { body fuselage;"
            " quantity position; component z; setPoint 0; } } } }"
        )
    );
    testMotion motion(runTime(), dict);
    ASSERT_TRUE(motion.controller());

    expectUsageKeys
    (
        usageKeys
        ({
            "controllers/flightController/flightController.H",
            "controllers/PID/PID.H"
        }),
        motion.controller()->allowedKeys()
    );
}


// ************************************************************************* //
