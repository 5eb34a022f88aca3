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
    GoogleTest unit tests of libflapFoamRunTools: the run-input checks
    (runInputCheck, functionObjectKeys) and runProgress's durations:
      - read: a number of the whole text, beyond a double (1e400, -1e309)
        refused without SIGFPE, an integer that is not one refused;
      - numbers: the first number beyond a double of a file named with its
        key and line; such numbers in comments, block comments and strings
        and inside words ignored;
      - controls: deltaT and writeInterval <= 0 refused naming the key and
        value, positive ones and their absence accepted;
      - functionObjectKeys: an unknown key named with the allowed ones, the
        standard keys of a function object accepted;
      - runProgress::duration: seconds, minutes, hours;
      - runProgress's cycleMotion found under imposedMotion or the paper
        authors' ImposedMotion (both: the error of the motions' list; none:
        "no such entry").

\*---------------------------------------------------------------------------*/

#include "runInputCheck.H"
#include "functionObjectKeys.H"
#include "dictionaryKeys.H"
#include "runProgress.H"
#include "scratchTime.H"
#include "IStringStream.H"
#include "OSspecific.H"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A scratch file with the text, removed on destruction
class scratchFile
{
    fileName path_;

public:

    explicit scratchFile(const std::string& text)
    :
        path_("/tmp/flapFoamTest-runInputCheck-" + Foam::name(pid()))
    {
        std::ofstream(path_.c_str()) << text;
    }

    ~scratchFile()
    {
        rm(path_);
    }

    const fileName& path() const
    {
        return path_;
    }
};


//- The message of the FatalIOError of f ("" if none)
template<class F>
std::string ioErrorOf(const F& f)
{
    try
    {
        f();
    }
    catch (const Foam::IOerror& err)
    {
        return err.message() + " @" + Foam::name(err.sourceFileLineNumber())
          + " " + err.ioFileName() + ":" + Foam::name(err.ioStartLineNumber());
    }
    return std::string();
}


//- A dictionary of text
dictionary dictOf(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * Tests  * * * * * * * * * * * * * * * //

TEST(runInputCheck, readNumbers)
{
    scalar s = -1;
    EXPECT_TRUE(runInputCheck::read("1.5e-3", s));
    EXPECT_EQ(s, 1.5e-3);
    EXPECT_FALSE(runInputCheck::read("1e400", s));
    EXPECT_FALSE(runInputCheck::read("-1e309", s));
    EXPECT_FALSE(runInputCheck::read("abc", s));
    EXPECT_FALSE(runInputCheck::read("0.25x", s));
    EXPECT_FALSE(runInputCheck::read("", s));
    EXPECT_EQ(s, 1.5e-3);

    label n = -1;
    EXPECT_TRUE(runInputCheck::read("12", n));
    EXPECT_EQ(n, 12);
    EXPECT_FALSE(runInputCheck::read("2.5", n));
    EXPECT_FALSE(runInputCheck::read("99999999999", n));
}


TEST(runInputCheck, numbersBeyondADouble)
{
    const scratchFile bad
    (
        "a 1;\nmotion\n{\n    amplitude   (0 2e308);\n}\nb -1e400;\n"
    );
    const std::string msg
    (
        ioErrorOf([&]{ runInputCheck::numbers(bad.path()); })
    );
    EXPECT_NE(msg.find("amplitude 2e308: beyond the range of a double"),
        std::string::npos) << msg;
    EXPECT_NE(msg.find(bad.path() + ":4"), std::string::npos) << msg;

    const scratchFile ignored
    (
        "a 1; // 1e400\n/* 1e999\n 1e999 */ b \"1e999\";\nc v1e400x;\n"
        "d (1e308 -1e-400);\n"
    );
    EXPECT_EQ(ioErrorOf([&]{ runInputCheck::numbers(ignored.path()); }), "");
}


TEST(runInputCheck, controls)
{
    for (const std::string entry : {"deltaT 0;", "writeInterval -1;"})
    {
        const scratchFile f("startTime 0;\n" + entry + "\n");
        const std::string msg
        (
            ioErrorOf([&]{ runInputCheck::controls(f.path()); })
        );
        EXPECT_NE(msg.find(entry.substr(0, entry.size() - 1)
            + ": a value > 0"), std::string::npos) << msg;
    }
    const scratchFile good("deltaT 1e-5;\nwriteInterval 0.0125;\n");
    EXPECT_EQ(ioErrorOf([&]{ runInputCheck::controls(good.path()); }), "");
    const scratchFile none("endTime 1;\n");
    EXPECT_EQ(ioErrorOf([&]{ runInputCheck::controls(none.path()); }), "");
}


TEST(functionObjectKeys, unknownAndStandardKeys)
{
    const wordList own({"rhoInf", "Uref"});
    const dictionary good
    (
        dictOf("type flightData; libs (\"a.so\"); enabled true; rhoInf 1;"
            " executeControl timeStep; writeControl writeTime;")
    );
    EXPECT_EQ(ioErrorOf([&]{ functionObjectKeys::check(good, own); }), "");

    const dictionary bad(dictOf("rhoInf 1; Urf 2;"));
    const std::string msg
    (
        ioErrorOf([&]{ functionObjectKeys::check(bad, own); })
    );
    EXPECT_NE(msg.find("Unknown key 'Urf'"), std::string::npos) << msg;
    EXPECT_NE
    (
        msg.find("allowed keys are rhoInf Uref (and those of every function"
            " object: type libs enabled"),
        std::string::npos
    ) << msg;

    // checkDictionaryKeys: the given keys alone
    const std::string only
    (
        ioErrorOf([&]{ checkDictionaryKeys(good, own); })
    );
    EXPECT_NE(only.find("allowed keys are rhoInf Uref"), std::string::npos)
        << only;
    EXPECT_EQ(only.find("every function object"), std::string::npos) << only;
}


//- The cycle period of runProgress with cycleMotion flapping, read from
//- a constant/dynamicMeshDict whose motions are under the given keys
//- (both: the error); the error message, empty if it constructed
std::string cycleMotionError(const wordList& keys)
{
    scratchTime runTime("flapFoamTest-runProgress", 1, 1);
    mkDir(runTime.dir()/"constant");
    std::ofstream os((runTime.dir()/"constant"/"dynamicMeshDict").c_str());
    os  << "FoamFile { version 2.0; format ascii; class dictionary;"
        << " object dynamicMeshDict; }\n"
        << "motionSolver eABAMeshMotion;\neABAMeshMotionCoeffs\n{\n";
    for (const word& key : keys)
    {
        os  << key << " { flapping { type wang; frequency 20; } }\n";
    }
    os  << "}\n";
    os.close();

    dictionary dict;
    dict.add("cycleMotion", "flapping");
    return ioErrorOf([&]{ functionObjects::runProgress("p", runTime(), dict); });
}


TEST(runProgress, cycleMotionInEitherSpelling)
{
    // flapFoam's spelling and the paper authors'
    EXPECT_EQ(cycleMotionError(wordList({"imposedMotion"})), "");
    EXPECT_EQ(cycleMotionError(wordList({"ImposedMotion"})), "");

    const std::string both(cycleMotionError(wordList({"imposedMotion",
        "ImposedMotion"})));
    EXPECT_NE(both.find("Both 'imposedMotion' and 'ImposedMotion'"),
        std::string::npos) << both;

    const std::string none(cycleMotionError(wordList()));
    EXPECT_NE(none.find("cycleMotion flapping: no such entry"),
        std::string::npos) << none;
}


TEST(runProgress, durations)
{
    using functionObjects::runProgress;
    EXPECT_EQ(runProgress::duration(12.345), "12.3 s");
    EXPECT_EQ(runProgress::duration(200), "3 min 20 s");
    EXPECT_EQ(runProgress::duration(8*3600 + 41*60 + 10), "8 h 41 min");
    EXPECT_EQ(runProgress::duration(0.25), "0.25 s");
}


// ************************************************************************* //
