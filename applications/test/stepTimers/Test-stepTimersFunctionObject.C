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
    GoogleTest unit tests of the stepTimers function object on a plain time
    loop, no mesh (flapFoamTest-stepTimers): the header and columns of
    stepTimers.dat, rbd + overset + pimple within 5 % of total in every
    step (and with preUpdate equal to it), a part first used later adds a
    header line, pimple = total without the mesh update stamps, the summary
    file, the per-rank file (its own means: rbd + overset + pimple +
    preUpdate within 5 % of total), a bad value, an unknown key.  The
    registry: Test-stepTimersRegistry.C.

    Sleeps are timed against loose upper bounds: the machine may be shared.

\*---------------------------------------------------------------------------*/

#include "stepTimers.H"
#include "stepTimersFunctionObject.H"
#include "scratchTime.H"
#include "stepTimersDat.H"
#include "stepTimersTestHelpers.H"
#include "OSspecific.H"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace Foam;
using namespace Foam::stepTimersTest;

// * * * * * * * * * * * * * * Function object  * * * * * * * * * * * * * * //

//- A run of nSteps steps timed as a solver times them (the parts
//- registered before the first step as timedOversetFvMesh does, the rbd
//- scope inside oversetMovePoints, oversetLate from lateStep on), with the
//- seconds slept in each step's scopes
struct timedSteps
{
    static constexpr label nSteps = 6;
    static constexpr label nStartup = 1;
    static constexpr label lateStep = 4;   // first step of oversetLate

    //- The scratch case (removed with the object)
    scratchTime runTimePtr;

    std::vector<scalar> sleptRbd, sleptMovePoints, sleptLate;
    fileName dir;

    timedSteps()
    :
        runTimePtr
        (
            "flapFoamTest-stepTimers", nSteps, 1,
            stepTimersFunctions(nStartup)
        )
    {
        Time& runTime = runTimePtr();
        stepTimers& timers = stepTimers::New(runTime);
        timers.add("oversetMovePoints", 0);

        while (runTime.loop())
        {
            // Solver work before the mesh update
            sleepMs(1);
            timers.stamp(stepTimers::meshUpdateStart);
            {
                stepTimers::scope t(timers, "oversetMovePoints");
                sleptMovePoints.push_back(sleepMs(3));
                {
                    stepTimers::scope t(timers, "rbd");
                    sleptRbd.push_back(sleepMs(2));
                }
            }
            sleptLate.push_back(0);
            if (runTime.timeIndex() >= lateStep)
            {
                stepTimers::scope t(timers, "oversetLate");
                sleptLate.back() = sleepMs(1);
            }
            timers.stamp(stepTimers::meshUpdated);

            // PIMPLE
            sleepMs(5);
        }
        dir = outputDir(runTime);
    }
};


//- The checks of row i of a timedSteps run's stepTimers.dat
void checkRow(const datFile& dat, const timedSteps& run, const size_t i)
{
    SCOPED_TRACE("row " + std::to_string(i));
    const bool late = label(i) + 1 >= timedSteps::lateStep;

    EXPECT_EQ(dat.headerOfRow[i], late ? 1u : 0u);
    EXPECT_DOUBLE_EQ(dat(i, "time"), i + 1);

    EXPECT_GE(dat(i, "rbd"), 0.002);
    EXPECT_LT(dat(i, "rbd"), run.sleptRbd[i] + margin);
    EXPECT_GE(dat(i, "oversetMovePoints"), 0.003);
    EXPECT_LT(dat(i, "oversetMovePoints"), run.sleptMovePoints[i] + margin);
    // Exact but for the file's 6 significant digits
    EXPECT_NEAR
    (
        dat(i, "overset"),
        dat(i, "oversetMovePoints") + (late ? dat(i, "oversetLate") : 0),
        2e-6*dat(i, "overset")
    );
    if (late)
    {
        EXPECT_GE(dat(i, "oversetLate"), 0.001);
    }
    EXPECT_GE(dat(i, "pimple"), 0.005);
    EXPECT_GE(dat(i, "preUpdate"), 0.001);

    const double sum = dat(i, "rbd") + dat(i, "overset") + dat(i, "pimple");
    EXPECT_LE(sum, dat(i, "total"));
    // The loop's deliberate pre-update sleep (preUpdate) belongs to none of
    // the three; on a busy machine it oversleeps
    EXPECT_NEAR
    (
        sum, dat(i, "total"), 0.05*dat(i, "total") + dat(i, "preUpdate") + 0.001
    );
    // With preUpdate the step is covered but for the loop's own overhead
    EXPECT_NEAR(sum + dat(i, "preUpdate"), dat(i, "total"), 2e-3);
}


TEST(stepTimersFunctionObject, headersAndRows)
{
    timedSteps run;
    ASSERT_TRUE(isFile(run.dir/"stepTimers.dat")) << run.dir;
    const datFile dat(run.dir/"stepTimers.dat");

    // Header at the first step, another when oversetLate appeared
    ASSERT_EQ(dat.headers.size(), 2u);
    const std::vector<std::string> first
    {
        "time", "rbd", "overset", "pimple", "total", "preUpdate",
        "oversetMovePoints"
    };
    EXPECT_EQ(dat.headers[0], first);
    std::vector<std::string> second(first);
    second.push_back("oversetLate");
    EXPECT_EQ(dat.headers[1], second);

    ASSERT_EQ(dat.rows.size(), size_t(timedSteps::nSteps));
    for (size_t i = 0; i < dat.rows.size(); ++i)
    {
        checkRow(dat, run, i);
    }

    // Reset after each step
    const stepTimers& timers = stepTimers::New(run.runTimePtr());
    EXPECT_EQ(timers["rbd"], 0);
    EXPECT_FALSE(timers.stamped(stepTimers::meshUpdated));
}


TEST(stepTimersFunctionObject, summary)
{
    const timedSteps run;
    const label nSteps = timedSteps::nSteps;
    const label nStartup = timedSteps::nStartup;

    // Steps after the start-up, total's share 1
    ASSERT_TRUE(isFile(run.dir/"stepTimersSummary.dat"));
    bool foundSteps = false;
    bool foundTotal = false;
    for (const std::string& line : readLines(run.dir/"stepTimersSummary.dat"))
    {
        const std::vector<std::string> w = split(line);
        if (w.size() >= 3 && w[0] == "#" && w[1] == "nSteps")
        {
            EXPECT_EQ(std::stoi(w[2]), nSteps - nStartup);
            foundSteps = true;
        }
        if (w.size() == 4 && w[0] == "total")
        {
            EXPECT_DOUBLE_EQ(std::stod(w[3]), 1);
            EXPECT_GE(std::stod(w[1]), 0.010);
            foundTotal = true;
        }
        if (w.size() == 4 && w[0] == "oversetLate")
        {
            // Zero in the steps before its first use
            const double meanLate = std::stod(w[1]);
            EXPECT_GE
            (
                meanLate,
                0.001*(nSteps - timedSteps::lateStep + 1)/(nSteps - 1)
            );
            scalar meanSlept = 0;
            for (label i = nStartup; i < nSteps; ++i)
            {
                meanSlept += run.sleptLate[i]/(nSteps - nStartup);
            }
            EXPECT_LT(meanLate, meanSlept + margin);
        }
    }
    EXPECT_TRUE(foundSteps);
    EXPECT_TRUE(foundTotal);

    // Per rank (one here): its own means, the same as the summary's
    ASSERT_TRUE(isFile(run.dir/"stepTimersRanks.dat"));
    std::vector<std::string> header, rank0;
    for (const std::string& line : readLines(run.dir/"stepTimersRanks.dat"))
    {
        const std::vector<std::string> w = split(line);
        if (w.size() > 2 && w[0] == "#" && w[1] == "rank")
        {
            header.assign(w.begin() + 1, w.end());
        }
        else if (!w.empty() && w[0] == "0")
        {
            rank0 = w;
        }
    }
    ASSERT_EQ(header.size(), rank0.size());
    EXPECT_EQ(std::stoi(rank0[1]), nSteps - nStartup);
    scalar parts = 0, total = 0;
    for (size_t i = 2; i < header.size(); ++i)
    {
        const scalar v = std::stod(rank0[i]);
        if (header[i] == "rbd" || header[i] == "overset"
         || header[i] == "pimple" || header[i] == "preUpdate")
        {
            parts += v;
        }
        if (header[i] == "total")
        {
            total = v;
        }
    }
    EXPECT_GE(total, 0.010);
    EXPECT_NEAR(parts, total, 0.05*total);
}


TEST(stepTimersFunctionObject, pimpleIsTotalWithoutStamp)
{
    scratchTime runTimePtr
    (
        "flapFoamTest-stepTimers",
        3,
        1,
        stepTimersFunctions(0)
    );
    Time& runTime = runTimePtr();

    while (runTime.loop())
    {
        sleepMs(4);
    }

    const datFile dat(outputDir(runTime)/"stepTimers.dat");
    ASSERT_EQ(dat.headers.size(), 1u);
    const std::vector<std::string> measured
    {
        "time", "rbd", "overset", "pimple", "total", "preUpdate"
    };
    EXPECT_EQ(dat.headers[0], measured);
    ASSERT_EQ(dat.rows.size(), 3u);
    for (size_t i = 0; i < dat.rows.size(); ++i)
    {
        EXPECT_EQ(dat(i, "rbd"), 0);
        EXPECT_EQ(dat(i, "overset"), 0);
        EXPECT_EQ(dat(i, "preUpdate"), 0);
        EXPECT_EQ(dat(i, "pimple"), dat(i, "total"));
        EXPECT_GE(dat(i, "total"), 0.004);
    }
}


TEST(stepTimersFunctionObject, badNStartup)
{
    scratchTime runTimePtr("flapFoamTest-stepTimers", 2, 1);

    dictionary dict;
    dict.add("nStartup", -1);

    // (Within a run, functionObjectList stops with the message)
    try
    {
        functionObjects::stepTimers fo("stepTimers", runTimePtr(), dict);
        ADD_FAILURE() << "nStartup -1 accepted";
    }
    catch (const Foam::IOerror& err)
    {
        EXPECT_NE(err.message().find("nStartup"), std::string::npos)
            << err.message();
    }
}


TEST(stepTimersFunctionObject, unknownKey)
{
    scratchTime runTimePtr("flapFoamTest-stepTimers", 2, 1);

    dictionary dict;
    dict.add("nStrtup", 1);

    try
    {
        functionObjects::stepTimers fo("stepTimers", runTimePtr(), dict);
        ADD_FAILURE() << "nStrtup accepted";
    }
    catch (const Foam::IOerror& err)
    {
        EXPECT_NE
        (
            err.message().find
            (
                "Unknown key 'nStrtup' in ; allowed keys are nStartup writePrecision"
            ),
            std::string::npos
        )   << err.message();
    }
}


// ************************************************************************* //
