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
    flapFoamTest-imposedMotion: imposedMotionList (the model's imposedMotion
    sub-dictionary): joints ascending, evaluate writes only the prescribed
    entries and checks the state size, empty without the sub-dictionary,
    write() round trip; joints out of range, on a multi-DoF joint,
    prescribed twice, or entries that are not dictionaries are
    FatalIOErrors naming the entry.

\*---------------------------------------------------------------------------*/

#include "imposedMotionTests.H"

// * * * * * * * * * * * * * * * imposedMotionList * * * * * * * * * * * * * //

namespace
{

const std::string modelText
(
    "bodies { }\n"
    "imposedMotion\n"
    "{\n"
    "    wing\n"
    "    {\n"
    "        type wangParametrization; jointList (5 1); Aphi 1.309;\n"
    "        fphi 20; Kphi 0.01; Aalpha 0.785; falpha 20; Kalpha 0.01;\n"
    "    }\n"
    "    shoulder { type harmonic; joint 3; amplitude 0.5; frequency 2; }\n"
    "    pitch\n"
    "    {\n"
    "        type wang; joint 0; waveform pitching; amplitude 0.3;\n"
    "        frequency 10; K 2;\n"
    "    }\n"
    "}\n"
);

//- Model with nDoF 1-DoF joints and the given imposedMotion entries
std::string modelWith(const std::string& entries)
{
    return "imposedMotion { " + entries + " }";
}

}


TEST(ImposedMotionList, JointsAscending)
{
    const imposedMotionList list(makeDict(modelText), labelList(7, 1));

    EXPECT_EQ(list.size(), 3);
    EXPECT_EQ(list.joints(), labelList({0, 1, 3, 5}));
    EXPECT_EQ(list[0].name(), "wing");
    EXPECT_EQ(list[2].type(), "wang");
}


TEST(ImposedMotionList, EvaluateWritesOnlyPrescribedEntries)
{
    const dictionary modelDict(makeDict(modelText));
    const imposedMotionList list(modelDict, labelList(7, 1));

    const scalar sentinel = 1234.5;
    scalarField q(7, sentinel), qDot(7, sentinel + 1), qDdot(7, sentinel + 2);

    const scalar t = 0.0123;
    list.evaluate(t, q, qDot, qDdot);

    // Prescribed entries: the motions' values
    auto wing = imposedMotion::New
    (
        "wing", modelDict.subDict("imposedMotion").subDict("wing")
    );
    auto shoulder = imposedMotion::New
    (
        "shoulder", modelDict.subDict("imposedMotion").subDict("shoulder")
    );
    auto pitch = imposedMotion::New
    (
        "pitch", modelDict.subDict("imposedMotion").subDict("pitch")
    );

    const auto expectJoint =
        [&](const label j, const imposedMotion& m, const label i)
        {
            const jointState s = eval(m, i, t);
            EXPECT_EQ(q[j], s.q) << "q[" << j << ']';
            EXPECT_EQ(qDot[j], s.qDot) << "qDot[" << j << ']';
            EXPECT_EQ(qDdot[j], s.qDdot) << "qDdot[" << j << ']';
        };

    expectJoint(5, *wing, 0);
    expectJoint(1, *wing, 1);
    expectJoint(3, *shoulder, 0);
    expectJoint(0, *pitch, 0);

    // The others untouched
    for (const label j : {2, 4, 6})
    {
        EXPECT_EQ(q[j], sentinel) << j;
        EXPECT_EQ(qDot[j], sentinel + 1) << j;
        EXPECT_EQ(qDdot[j], sentinel + 2) << j;
    }
}


TEST(ImposedMotionList, EmptyWithoutSubDictionary)
{
    const imposedMotionList list
    (
        makeDict("bodies { } joints { }"), labelList(4, 1)
    );

    EXPECT_EQ(list.size(), 0);
    EXPECT_TRUE(list.joints().empty());

    scalarField q(4, 1.5), qDot(4, 2.5), qDdot(4, 3.5);
    list.evaluate(0.1, q, qDot, qDdot);
    for (label j = 0; j < 4; ++j)
    {
        EXPECT_EQ(q[j], 1.5);
        EXPECT_EQ(qDot[j], 2.5);
        EXPECT_EQ(qDdot[j], 3.5);
    }

    // Empty sub-dictionary: also empty
    const imposedMotionList list2
    (
        makeDict("imposedMotion { }"), labelList(4, 1)
    );
    EXPECT_EQ(list2.size(), 0);
    EXPECT_TRUE(list2.joints().empty());

    // Default constructed
    const imposedMotionList list3;
    EXPECT_TRUE(list3.joints().empty());
}


TEST(ImposedMotionList, AuthorsSpelling)
{
    // The paper authors' code reads the sub-dictionary ImposedMotion
    std::string authors(modelText);
    authors.replace(authors.find("imposedMotion"), 13, "ImposedMotion");

    const imposedMotionList ours(makeDict(modelText), labelList(7, 1));
    const imposedMotionList theirs(makeDict(authors), labelList(7, 1));

    EXPECT_EQ(theirs.size(), 3);
    EXPECT_EQ(theirs.joints(), ours.joints());

    scalarField q1(7, Zero), qDot1(7, Zero), qDdot1(7, Zero);
    scalarField q2(7, Zero), qDot2(7, Zero), qDdot2(7, Zero);
    ours.evaluate(0.0123, q1, qDot1, qDdot1);
    theirs.evaluate(0.0123, q2, qDot2, qDdot2);
    EXPECT_EQ(q1, q2);
    EXPECT_EQ(qDot1, qDot2);
    EXPECT_EQ(qDdot1, qDdot2);

    // Written with flapFoam's spelling
    OStringStream os;
    theirs.write(os);
    EXPECT_TRUE(makeDict(os.str()).found("imposedMotion"));
}


TEST(ImposedMotionList, WriteRoundTrips)
{
    const imposedMotionList list(makeDict(modelText), labelList(7, 1));

    OStringStream os;
    os.precision(17);
    list.write(os);

    const imposedMotionList list2(makeDict(os.str()), labelList(7, 1));

    EXPECT_EQ(list2.size(), list.size()) << os.str();
    EXPECT_EQ(list2.joints(), list.joints()) << os.str();

    scalarField q1(7, 0), qDot1(7, 0), qDdot1(7, 0);
    scalarField q2(7, 0), qDot2(7, 0), qDdot2(7, 0);
    list.evaluate(0.0217, q1, qDot1, qDdot1);
    list2.evaluate(0.0217, q2, qDot2, qDdot2);
    for (label j = 0; j < 7; ++j)
    {
        EXPECT_NEAR(q2[j], q1[j], 1e-12);
        EXPECT_NEAR(qDot2[j], qDot1[j], 1e-9);
        EXPECT_NEAR(qDdot2[j], qDdot1[j], 1e-6);
    }
}


TEST(ImposedMotionList, EvaluateChecksStateSize)
{
    const imposedMotionList list(makeDict(modelText), labelList(7, 1));
    scalarField q(5, 0), qDot(5, 0), qDdot(5, 0);

    try
    {
        list.evaluate(0, q, qDot, qDdot);
        ADD_FAILURE() << "no FatalError for a state smaller than the joints";
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find("too small"), std::string::npos) << msg;
    }
}


TEST(Errors, ImposedMotionListJointOutOfRange)
{
    const labelList jointDoF(6, 1);

    for (const char* j : {"-1", "6"})
    {
        SCOPED_TRACE(j);
        expectIOError
        (
            [&]()
            {
                imposedMotionList
                (
                    makeDict
                    (
                        modelWith
                        (
                            "flap { type harmonic; amplitude 1; frequency 2;"
                            " joint " + std::string(j) + "; }"
                        )
                    ),
                    jointDoF
                );
            },
            {"'joint'", "'flap'", std::string("joint ") + j, "0..5"}
        );
    }

    // jointList names its own key
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict(modelWith("wing { " + wangParametrizationText("")
                  + " }")),
                labelList(4, 1)         // jointList (3 4): 4 out of range
            );
        },
        {"'jointList'", "'wing'", "joint 4", "0..3"}
    );
}


TEST(Errors, ImposedMotionListMultiDoFJoint)
{
    // q indices 2, 3, 4 belong to a 3-DoF joint (e.g. spherical)
    const labelList jointDoF({1, 1, 3, 3, 3, 1});

    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict
                (
                    modelWith
                    (
                        "flap { type harmonic; joint 3; amplitude 1;"
                        " frequency 2; }"
                    )
                ),
                jointDoF
            );
        },
        {
            "'joint'", "'flap'", "joint 3",
            "belongs to a joint with 3 degrees of freedom",
            "only 1-DoF joints can be prescribed"
        }
    );

    // The 1-DoF ones are fine
    EXPECT_NO_THROW
    (
        imposedMotionList
        (
            makeDict
            (
                modelWith
                (
                    "flap { type harmonic; joint 5; amplitude 1;"
                    " frequency 2; }"
                )
            ),
            jointDoF
        )
    );
}


TEST(Errors, ImposedMotionListJointPrescribedTwice)
{
    const labelList jointDoF(6, 1);

    // By two entries: both named
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict
                (
                    modelWith
                    (
                        "left { type harmonic; joint 2; amplitude 1;"
                        " frequency 2; }"
                        " right { type wang; joint 2; waveform flapping;"
                        " amplitude 1; frequency 2; K 0.5; }"
                    )
                ),
                jointDoF
            );
        },
        {"joint 2", "prescribed twice", "'left'", "'right'"}
    );

    // Twice in one entry: wangParametrization jointList (2 2)
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict
                (
                    modelWith
                    (
                        "wing { type wangParametrization; jointList (2 2);"
                        " Aphi 1; fphi 20; Kphi 0.5; Aalpha 1; falpha 20;"
                        " Kalpha 1; }"
                    )
                ),
                jointDoF
            );
        },
        {
            "'jointList'", "'wing'", "joint 2", "prescribed twice",
            "appears twice"
        }
    );
}


TEST(Errors, ImposedMotionListNotDictionaries)
{
    // An entry that is not a motion dictionary
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict(modelWith("flap 3;")), labelList(4, 1)
            );
        },
        {"'flap'", "not a dictionary"}
    );

    // imposedMotion itself not a dictionary
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict("imposedMotion none;"), labelList(4, 1)
            );
        },
        {"'imposedMotion'", "not a dictionary"}
    );
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict("ImposedMotion none;"), labelList(4, 1)
            );
        },
        {"'ImposedMotion'", "not a dictionary"}
    );
}


TEST(Errors, ImposedMotionListBothSpellings)
{
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict(modelText + "ImposedMotion { }"), labelList(7, 1)
            );
        },
        {"'imposedMotion'", "'ImposedMotion'", "Both", "one of them"}
    );
}


// ************************************************************************* //
