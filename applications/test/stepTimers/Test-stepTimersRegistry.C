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
    GoogleTest unit tests of the step timers' registry (flapFoamTest-
    stepTimers): a scope adds its elapsed time, parts stay in the order of
    first use, reset zeroes the parts and clears the stamps but keeps the
    names, New returns the same object for the Time database and any
    registry on it, nested scopes and adds inside a scope are exclusive,
    stamps; laps from a stamp exclude the scopes inside them and add up
    with them to the elapsed time, the trailing lap goes to its part at
    endLap (and not after a reset); counts add up and take nothing from
    scopes or laps; without a manual clock the timers read the steady
    clock.  The function object: Test-stepTimersFunctionObject.C.

    The timers read a manual clock (stepTimersTestHelpers.H): every time is
    exact, to round-off, whatever the machine's load.

\*---------------------------------------------------------------------------*/

#include "stepTimers.H"
#include "scratchTime.H"
#include "stepTimersTestHelpers.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::stepTimersTest;

// * * * * * * * * * * * * * * * * Registry * * * * * * * * * * * * * * * * //

TEST(stepTimersRegistry, scopeAddsElapsedTime)
{
    manualClock clock;
    scratchTime runTime("flapFoamTest-stepTimers", 1, 1);
    stepTimers& timers = stepTimers::New(runTime());

    {
        stepTimers::scope timer(timers, "rbd");
        clock.advance(20);
    }
    EXPECT_NEAR(timers["rbd"], 0.020, roundOff);

    // A second scope adds to the part; time outside scopes goes nowhere
    clock.advance(7);
    {
        stepTimers::scope timer(timers, "rbd");
        clock.advance(20);
    }
    EXPECT_NEAR(timers["rbd"], 0.040, roundOff);
    EXPECT_EQ(timers["never"], 0);
    EXPECT_EQ(timers.nOpen(), 0);
}


TEST(stepTimersRegistry, steadyClockWithoutManualClock)
{
    // The default source: a reading between two of the steady clock
    const auto before = stepTimers::clock::now();
    const auto reading = stepTimers::now();
    const auto after = stepTimers::clock::now();
    EXPECT_TRUE(before <= reading);
    EXPECT_TRUE(reading <= after);

    // And again after a manual clock is gone
    {
        manualClock clock;
        EXPECT_TRUE(stepTimers::now() == stepTimers::clock::time_point());
    }
    EXPECT_TRUE(stepTimers::now() >= after);
}


TEST(stepTimersRegistry, partsInOrderOfFirstUse)
{
    manualClock clock;
    scratchTime runTime("flapFoamTest-stepTimers", 1, 1);
    stepTimers& timers = stepTimers::New(runTime());

    timers.add("pimple", 1);
    timers.add("overset", 2);
    timers.add("pimple", 3);
    timers.add("rbd", 0);
    {
        stepTimers::scope timer(timers, "overset");
        clock.advance(5);
    }

    const wordList expected({"pimple", "overset", "rbd"});
    ASSERT_EQ(timers.parts().size(), expected.size());
    forAll(expected, i)
    {
        EXPECT_EQ(timers.parts()[i], expected[i]);
    }
    EXPECT_EQ(timers["pimple"], 4);
    EXPECT_NEAR(timers["overset"], 2.005, roundOff);
    EXPECT_EQ(timers["rbd"], 0);
}


TEST(stepTimersRegistry, resetZeroesPartsAndClearsStamps)
{
    scratchTime runTime("flapFoamTest-stepTimers", 1, 1);
    stepTimers& timers = stepTimers::New(runTime());

    timers.add("a", 1.5);
    timers.add("b", 2.5);
    timers.stamp("meshUpdated");
    ASSERT_TRUE(timers.stamped("meshUpdated"));

    timers.reset();

    ASSERT_EQ(timers.parts().size(), 2);
    EXPECT_EQ(timers.parts()[0], "a");
    EXPECT_EQ(timers.parts()[1], "b");
    EXPECT_EQ(timers["a"], 0);
    EXPECT_EQ(timers["b"], 0);
    EXPECT_FALSE(timers.stamped("meshUpdated"));

    timers.add("a", 1);
    EXPECT_EQ(timers["a"], 1);
}


TEST(stepTimersRegistry, newReturnsTheSameObject)
{
    scratchTime runTime("flapFoamTest-stepTimers", 1, 1);

    stepTimers& a = stepTimers::New(runTime());
    stepTimers& b = stepTimers::New(runTime());
    EXPECT_EQ(&a, &b);

    // A registry on the Time database (as a mesh is) gives the Time's
    objectRegistry sub
    (
        IOobject("sub", runTime().timeName(), runTime())
    );
    EXPECT_EQ(&stepTimers::New(sub), &a);

    a.add("rbd", 1);
    EXPECT_EQ(stepTimers::New(sub)["rbd"], 1);

    // Another Time database has its own
    scratchTime other("flapFoamTest-stepTimers", 1, 1);
    EXPECT_NE(&stepTimers::New(other()), &a);
    EXPECT_EQ(stepTimers::New(other())["rbd"], 0);
}


TEST(stepTimersRegistry, nestedScopesAreExclusive)
{
    manualClock clock;
    scratchTime runTime("flapFoamTest-stepTimers", 1, 1);
    stepTimers& timers = stepTimers::New(runTime());

    const auto start = stepTimers::now();
    {
        stepTimers::scope outer(timers, "oversetMovePoints");
        clock.advance(10);
        {
            stepTimers::scope inner(timers, "rbd");
            clock.advance(20);
            {
                stepTimers::scope innermost(timers, "rbdForces");
                clock.advance(10);
            }
            EXPECT_EQ(timers.nOpen(), 2);
        }
        timers.add("oversetStencil", 0.005);   // counts as nested too
    }
    const scalar elapsed = stepTimers::seconds(start, stepTimers::now());

    EXPECT_EQ(timers.nOpen(), 0);
    EXPECT_NEAR(elapsed, 0.040, roundOff);
    EXPECT_NEAR(timers["rbdForces"], 0.010, roundOff);
    EXPECT_NEAR(timers["rbd"], 0.020, roundOff);
    EXPECT_NEAR(timers["oversetMovePoints"], 0.010 - 0.005, roundOff);

    // The parts add up to the outer scope
    const scalar sum =
        timers["rbdForces"] + timers["rbd"] + timers["oversetStencil"]
      + timers["oversetMovePoints"];
    EXPECT_NEAR(sum, elapsed, roundOff);

    // Outside any scope an add does not nest
    timers.add("pimple", 1);
    EXPECT_EQ(timers.nOpen(), 0);
}


TEST(stepTimersRegistry, stamps)
{
    manualClock clock;
    scratchTime runTime("flapFoamTest-stepTimers", 1, 1);
    stepTimers& timers = stepTimers::New(runTime());

    EXPECT_FALSE(timers.stamped(stepTimers::meshUpdated));
    EXPECT_THROW(timers.stampTime(stepTimers::meshUpdated), Foam::error);

    clock.advance(3);
    const auto first = stepTimers::now();
    timers.stamp(stepTimers::meshUpdated);
    ASSERT_TRUE(timers.stamped(stepTimers::meshUpdated));
    EXPECT_TRUE(timers.stampTime(stepTimers::meshUpdated) == first);

    // A later stamp of the same name replaces it
    clock.advance(5);
    timers.stamp(stepTimers::meshUpdated);
    EXPECT_NEAR
    (
        stepTimers::seconds(first, timers.stampTime(stepTimers::meshUpdated)),
        0.005,
        roundOff
    );
}


TEST(stepTimersRegistry, lapsExcludeTheScopesInside)
{
    manualClock clock;
    scratchTime runTime("flapFoamTest-stepTimers", 1, 1);
    stepTimers& timers = stepTimers::New(runTime());

    // From the stamp: 10 ms, a 20 ms scope (nested: excluded), 10 ms
    timers.stamp(stepTimers::meshUpdated);
    const auto start = stepTimers::now();
    clock.advance(10);
    {
        stepTimers::scope solve(timers, "pimplePressureSolve");
        clock.advance(20);
    }
    clock.advance(10);
    const auto lapEnd = timers.lap("pimpleMomentum");

    EXPECT_TRUE(lapEnd == stepTimers::now());
    EXPECT_NEAR(timers["pimpleMomentum"], 0.020, roundOff);
    EXPECT_NEAR(timers["pimplePressureSolve"], 0.020, roundOff);

    // The next lap starts where this one ended; the trailing stretch goes
    // to its part at endLap (the function object's execute)
    clock.advance(10);
    timers.lap("pimplePressure");
    timers.trailingLap("pimpleTurbulence");
    clock.advance(15);
    EXPECT_TRUE(timers.endLap());
    const scalar elapsed = stepTimers::seconds(start, stepTimers::now());

    EXPECT_NEAR(timers["pimplePressure"], 0.010, roundOff);
    EXPECT_NEAR(timers["pimpleTurbulence"], 0.015, roundOff);
    const scalar sum =
        timers["pimpleMomentum"] + timers["pimplePressureSolve"]
      + timers["pimplePressure"] + timers["pimpleTurbulence"];
    EXPECT_NEAR(sum, elapsed, roundOff);

    // Without a trailing part endLap adds nothing; reset clears it
    const scalar turbulence = timers["pimpleTurbulence"];
    clock.advance(5);
    EXPECT_FALSE(timers.endLap());
    EXPECT_EQ(timers["pimpleTurbulence"], turbulence);
    timers.trailingLap("pimpleTurbulence");
    timers.reset();
    EXPECT_FALSE(timers.endLap());
    EXPECT_EQ(timers["pimpleTurbulence"], 0);
}


TEST(stepTimersRegistry, countsAreNotSeconds)
{
    manualClock clock;
    scratchTime runTime("flapFoamTest-stepTimers", 1, 1);
    stepTimers& timers = stepTimers::New(runTime());

    timers.stamp(stepTimers::meshUpdated);
    {
        stepTimers::scope solve(timers, "pimplePressureSolve");
        timers.count("pIterations1", 17);
        clock.advance(10);
    }
    timers.count("pIterations1", 3);
    clock.advance(10);
    timers.lap("pimplePressure");

    EXPECT_EQ(timers["pIterations1"], 20);
    EXPECT_TRUE(timers.isCount("pIterations1"));
    EXPECT_FALSE(timers.isCount("pimplePressure"));

    // Neither the scope nor the lap lost the counted "seconds"
    EXPECT_NEAR(timers["pimplePressureSolve"], 0.010, roundOff);
    EXPECT_NEAR(timers["pimplePressure"], 0.010, roundOff);
}

// ************************************************************************* //
