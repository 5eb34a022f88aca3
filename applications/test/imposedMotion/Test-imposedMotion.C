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
    flapFoamTest-imposedMotion: the base class imposedMotion and its
    selector: write() then read back gives the same motion for every type;
    an unknown type lists the valid ones; missing keys and a frequency that
    is not positive are FatalIOErrors naming the key, for every type.

\*---------------------------------------------------------------------------*/

#include "imposedMotionTests.H"

// * * * * * * * * * * * * * * * * write/read  * * * * * * * * * * * * * * * //

TEST(WriteRead, EveryTypeRoundTrips)
{
    const std::vector<std::string> texts
    {
        "type harmonic; joint 0; amplitude 0.9948; frequency 2; phase 0.3;"
        " offset -0.9948;",
        "type wang; joint 1; waveform flapping; amplitude 1.309;"
        " frequency 20; K 0.9; phase 0.1; offset 0.05;",
        "type wang; joint 1; waveform pitching; amplitude 0.785;"
        " frequency 20; K 5;",
        wangParametrizationText("motionType midStart;"),
        "type fourier; joint 2; frequency 20; a (1.2 0.1); b (0 0.3);",
        "type fourier; joint 2; frequency 20; b (0.3);",
        "type tabulated; joint 0; offset 0.2; " + valuesEntry(tabT, tabQ)
    };

    for (const std::string& text : texts)
    {
        SCOPED_TRACE(text);
        auto m1 = makeMotion(text);
        const std::string written(writtenText(*m1));
        auto m2 = makeMotion(written);

        EXPECT_EQ(m2->type(), m1->type()) << written;
        EXPECT_EQ(m2->joints(), m1->joints()) << written;

        forAll(m1->joints(), i)
        {
            for (label k = 0; k < 20; ++k)
            {
                const scalar t = 0.00713*k - 0.03;
                const jointState a = eval(*m1, i, t);
                const jointState b = eval(*m2, i, t);
                EXPECT_NEAR(a.q, b.q, 1e-12*(1 + mag(a.q))) << written;
                EXPECT_NEAR(a.qDot, b.qDot, 1e-10*(1 + mag(a.qDot)));
                EXPECT_NEAR(a.qDdot, b.qDdot, 1e-8*(1 + mag(a.qDdot)));
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Bad input * * * * * * * * * * * * * * * * //

TEST(Errors, UnknownTypeListsValidTypes)
{
    expectMotionError
    (
        "type sinus; joint 0; amplitude 1; frequency 1;",
        {
            "Unknown imposedMotion type sinus",
            "fourier", "harmonic", "tabulated", "wang", "wangParametrization"
        }
    );
}


TEST(Errors, UnknownKeyListsAllowedKeys)
{
    // A misspelled optional key of every type: FatalIOError naming it and
    // listing the type's keys
    expectMotionError
    (
        "type harmonic; joint 0; amplitude 1; frequency 2; phse 0.5;",
        {"'phse'", "harmonic", "allowed keys", "phase", "offset", "joint"}
    );
    expectMotionError
    (
        "type wang; joint 0; waveform flapping; amplitude 1; frequency 2;"
        " K 0.5; ofset 1;",
        {"'ofset'", "allowed keys", "waveform", "K", "phase", "offset"}
    );
    expectMotionError
    (
        "type fourier; joint 0; frequency 2; a (1); A0 1;",
        {"'A0'", "allowed keys", "a0", "frequency"}
    );
    expectMotionError
    (
        "type tabulated; joint 0; offest 1; " + valuesEntry(tabT, tabQ),
        {"'offest'", "allowed keys", "values", "file", "offset"}
    );
    expectMotionError
    (
        wangParametrizationText("Kphy 0.3;"),
        {"'Kphy'", "allowed keys", "Kphi", "jointList"}
    );

    // The joints key of another type is unknown too
    expectMotionError
    (
        "type harmonic; jointList (0 1); joint 0; amplitude 1; frequency 2;",
        {"'jointList'", "allowed keys", "joint"}
    );
}


TEST(Errors, MissingKeys)
{
    expectMotionError("joint 0; amplitude 1; frequency 1;", {"'type'"});
    expectMotionError
    (
        "type harmonic; joint 0; frequency 2;", {"'amplitude'"}
    );
    expectMotionError
    (
        "type harmonic; amplitude 1; frequency 2;", {"'joint'"}
    );
    expectMotionError
    (
        "type harmonic; joint 0; amplitude 1;", {"'frequency'"}
    );
    expectMotionError
    (
        "type wang; joint 0; waveform flapping; amplitude 1; frequency 2;",
        {"'K'"}
    );
    expectMotionError
    (
        "type wang; joint 0; amplitude 1; frequency 2; K 0.5;",
        {"'waveform'"}
    );
    expectMotionError
    (
        "type wangParametrization; Aphi 1; fphi 20; Kphi 0.5;"
        " Aalpha 1; falpha 20; Kalpha 1;",
        {"'jointList'"}
    );
    expectMotionError
    (
        "type wangParametrization; jointList (0 1); fphi 20; Kphi 0.5;"
        " Aalpha 1; falpha 20; Kalpha 1;",
        {"'Aphi'"}
    );
    expectMotionError
    (
        "type wangParametrization; jointList (0 1); Aphi 1; fphi 20;"
        " Kphi 0.5; Aalpha 1; falpha 20;",
        {"'Kalpha'"}
    );
    expectMotionError("type fourier; joint 0; a (1);", {"'frequency'"});
}


TEST(Errors, FrequencyNotPositive)
{
    for (const char* f : {"0", "-1"})
    {
        const std::string fs(f);
        expectMotionError
        (
            "type harmonic; joint 0; amplitude 1; frequency " + fs + ";",
            {"frequency " + fs + ":", "a value > 0 is allowed"}
        );
        expectMotionError
        (
            "type wang; joint 0; waveform pitching; amplitude 1; K 1;"
            " frequency " + fs + ";",
            {"frequency " + fs + ":", "a value > 0 is allowed"}
        );
        expectMotionError
        (
            "type fourier; joint 0; a (1); frequency " + fs + ";",
            {"frequency " + fs + ":", "a value > 0 is allowed"}
        );
        expectMotionError
        (
            "type wangParametrization; jointList (0 1); Aphi 1; Kphi 0.5;"
            " Aalpha 1; falpha 20; Kalpha 1; fphi " + fs + ";",
            {"fphi " + fs + ":", "a value > 0 is allowed"}
        );
        expectMotionError
        (
            "type wangParametrization; jointList (0 1); Aphi 1; Kphi 0.5;"
            " Aalpha 1; fphi 20; Kalpha 1; falpha " + fs + ";",
            {"falpha " + fs + ":", "a value > 0 is allowed"}
        );
    }
}


// ************************************************************************* //
