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
    stepTimers.dat, every column of every step as timed, rbd + overset +
    pimple + preUpdate = total and the laps (pimpleMomentum,
    pimpleTurbulence, pimpleSync) = pimple in every step, a part first used
    later adds a header line, pimple = total and no pimpleSync without the
    mesh update stamps and laps, the summary file, the per-rank file (its
    own means, adding up likewise), a bad value, an unknown key.  The
    registry: Test-stepTimersRegistry.C.

    The timers read a manual clock (stepTimersTestHelpers.H): the values
    are exact but for the files' 6 significant digits.

\*---------------------------------------------------------------------------*/

#include "stepTimers.H"
#include "stepTimersFunctionObject.H"
#include "scratchTime.H"
#include "stepTimersDat.H"
#include "stepTimersTestHelpers.H"
#include "OSspecific.H"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

using namespace Foam;
using namespace Foam::stepTimersTest;

//- What the files' 6 significant digits keep of a value v
inline double written(const double v)
{
    return 1e-6*std::abs(v) + roundOff;
}

// * * * * * * * * * * * * * * Function object  * * * * * * * * * * * * * * //

//- A run of nSteps steps timed as a solver times them (the parts
//- registered before the first step as timedOversetFvMesh does, the rbd
//- scope inside oversetMovePoints, oversetLate from lateStep on, the laps
//- of the fvOption pimpleTimers), on the manual clock: per step 1 ms
//- before the update, 3 ms oversetMovePoints, 2 ms rbd, 1 ms oversetLate,
//- 2 ms pimpleMomentum, 3 ms pimpleTurbulence
struct timedSteps
{
    static constexpr label nSteps = 6;
    static constexpr label nStartup = 1;
    static constexpr label lateStep = 4;   // first step of oversetLate

    //- The timers' clock (before the case: every reading is manual)
    manualClock clock;

    //- The scratch case (removed with the object)
    scratchTime runTimePtr;

    fileName dir;

    timedSteps()
    :
        clock(),
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
            clock.advance(1);                   // before the mesh update
            timers.stamp(stepTimers::meshUpdateStart);
            {
                stepTimers::scope t(timers, "oversetMovePoints");
                clock.advance(3);
                {
                    stepTimers::scope t(timers, "rbd");
                    clock.advance(2);
                }
            }
            if (runTime.timeIndex() >= lateStep)
            {
                stepTimers::scope t(timers, "oversetLate");
                clock.advance(1);
            }
            timers.stamp(stepTimers::meshUpdated);

            // PIMPLE, split by laps
            clock.advance(2);
            timers.lap("pimpleMomentum");
            timers.trailingLap("pimpleTurbulence");
            clock.advance(3);
        }
        dir = outputDir(runTime);
    }
};


//- The checks of row i of a timedSteps run's stepTimers.dat
void checkRow(const datFile& dat, const size_t i)
{
    SCOPED_TRACE("row " + std::to_string(i));
    const bool late = label(i) + 1 >= timedSteps::lateStep;
    const double lateSeconds = late ? 0.001 : 0;

    EXPECT_EQ(dat.headerOfRow[i], late ? 1u : 0u);
    EXPECT_DOUBLE_EQ(dat(i, "time"), i + 1);

    const std::vector<std::pair<std::string, double>> expected
    {
        {"rbd", 0.002},
        {"oversetMovePoints", 0.003},
        {"overset", 0.003 + lateSeconds},
        {"pimpleMomentum", 0.002},
        {"pimpleTurbulence", 0.003},
        {"pimpleSync", 0},
        {"pimple", 0.005},
        {"preUpdate", 0.001},
        {"total", 0.011 + lateSeconds}
    };
    for (const auto& column : expected)
    {
        EXPECT_NEAR(dat(i, column.first), column.second, written(column.second))
            << column.first;
    }
    if (late)
    {
        EXPECT_NEAR(dat(i, "oversetLate"), 0.001, written(0.001));
    }

    // The identities the columns hold by construction
    const double total = dat(i, "total");
    EXPECT_NEAR
    (
        dat(i, "rbd") + dat(i, "overset") + dat(i, "pimple")
      + dat(i, "preUpdate"),
        total,
        4*written(total)
    );
    EXPECT_NEAR
    (
        dat(i, "pimpleMomentum") + dat(i, "pimpleTurbulence")
      + dat(i, "pimpleSync"),
        dat(i, "pimple"),
        3*written(dat(i, "pimple"))
    );
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
        "oversetMovePoints", "pimpleMomentum", "pimpleTurbulence",
        "pimpleSync"
    };
    EXPECT_EQ(dat.headers[0], first);
    std::vector<std::string> second(first);
    second.push_back("oversetLate");
    EXPECT_EQ(dat.headers[1], second);

    ASSERT_EQ(dat.rows.size(), size_t(timedSteps::nSteps));
    for (size_t i = 0; i < dat.rows.size(); ++i)
    {
        checkRow(dat, i);
    }

    // Reset after each step
    const stepTimers& timers = stepTimers::New(run.runTimePtr());
    EXPECT_EQ(timers["rbd"], 0);
    EXPECT_FALSE(timers.stamped(stepTimers::meshUpdated));
}


//- The summary file's rows {name: words} and its "# nSteps" count
std::map<std::string, std::vector<std::string>> summaryRows
(
    const fileName& file,
    label& nSteps
)
{
    std::map<std::string, std::vector<std::string>> rows;
    nSteps = -1;
    for (const std::string& line : readLines(file))
    {
        const std::vector<std::string> w = split(line);
        if (w.size() >= 3 && w[0] == "#" && w[1] == "nSteps")
        {
            nSteps = std::stoi(w[2]);
        }
        else if (w.size() == 4 && w[0] != "#")
        {
            rows[w[0]] = w;
        }
    }
    return rows;
}


TEST(stepTimersFunctionObject, summary)
{
    const timedSteps run;
    const label nSteps = timedSteps::nSteps;
    const label nStartup = timedSteps::nStartup;
    const label nSummarised = nSteps - nStartup;
    const label nLate = nSteps - timedSteps::lateStep + 1;

    // Steps after the start-up, total's share 1
    ASSERT_TRUE(isFile(run.dir/"stepTimersSummary.dat"));
    label nFound = 0;
    auto rows = summaryRows(run.dir/"stepTimersSummary.dat", nFound);
    EXPECT_EQ(nFound, nSummarised);

    const double meanTotal = 0.011 + 0.001*nLate/nSummarised;
    ASSERT_EQ(rows.count("total"), 1u);
    EXPECT_DOUBLE_EQ(std::stod(rows["total"][3]), 1);
    EXPECT_NEAR(std::stod(rows["total"][1]), meanTotal, written(meanTotal));

    // A part first used later counts zero in the steps before
    ASSERT_EQ(rows.count("oversetLate"), 1u);
    const double meanLate = 0.001*nLate/nSummarised;
    EXPECT_NEAR(std::stod(rows["oversetLate"][1]), meanLate, written(meanLate));

    // Per rank (one here): its own means, adding up as the rows do
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
    EXPECT_EQ(std::stoi(rank0[1]), nSummarised);
    std::map<std::string, double> mean;
    for (size_t i = 2; i < header.size(); ++i)
    {
        mean[header[i]] = std::stod(rank0[i]);
    }
    EXPECT_NEAR(mean["total"], meanTotal, written(meanTotal));
    EXPECT_NEAR
    (
        mean["rbd"] + mean["overset"] + mean["pimple"] + mean["preUpdate"],
        mean["total"],
        4*written(meanTotal)
    );
    EXPECT_NEAR
    (
        mean["pimpleMomentum"] + mean["pimpleTurbulence"]
      + mean["pimpleSync"],
        mean["pimple"],
        3*written(mean["pimple"])
    );
}


TEST(stepTimersFunctionObject, pimpleIsTotalWithoutStampOrLaps)
{
    manualClock clock;
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
        clock.advance(4);
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
        EXPECT_NEAR(dat(i, "total"), 0.004, written(0.004));
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
