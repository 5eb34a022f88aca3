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

#include "wangParametrization.H"
#include "dictionaryRead.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace imposedMotions
{
    defineTypeNameAndDebug(wangParametrization, 0);
    addToRunTimeSelectionTable(imposedMotion, wangParametrization, dictionary);

    // The keys of the Usage table besides type
    static const imposedMotion::addTypeKeys addwangParametrizationKeys_
    (
        imposedMotions::wangParametrization::typeName,
        {
            "jointList",
            wordList
            ({
                "motionType", "Aphi", "fphi", "Kphi", "Aalpha", "falpha",
                "Kalpha"
            }),
            wordList({"body", "initialConditions"}),
            [](const dictionary& dict)
            {
                wangParametrization::readMotionType(dict);
            }
        }
    );
}
}


const Foam::Enum<Foam::imposedMotions::wangParametrization::motionType>
Foam::imposedMotions::wangParametrization::motionTypeNames
({
    { motionType::standard, "standard" },
    { motionType::midStart, "midStart" },
    { motionType::midStart2Wings, "midStart_2wings" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::imposedMotions::wangParametrization::readJointList
(
    const dictionary& dict
)
{
    const labelList joints(dict.get<labelList>("jointList"));
    const motionType type = readMotionType(dict);
    const label nJoints = type == motionType::midStart2Wings ? 4 : 2;

    if (joints.size() != nJoints)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'jointList' has " << joints.size()
            << " entries: motionType " << motionTypeNames[type]
            << " needs exactly " << nJoints
            << (
                   nJoints == 2
                 ? " (flapping joint, pitching joint)"
                 : " (flapping 1, pitching 1, flapping 2, pitching 2)"
               )
            << nl << exit(FatalIOError);
    }

    return joints;
}


Foam::imposedMotions::wangParametrization::motionType
Foam::imposedMotions::wangParametrization::readMotionType
(
    const dictionary& dict
)
{
    const word name(dict.getOrDefault<word>("motionType", word::null));

    // The authors' controllers (midStartControl_z_PD, ..._xzth_PD, ...)
    // are named as such; their xzth ones convert to flapFoam's controller
    if (name.starts_with("midStartControl"))
    {
        FatalIOErrorInFunction(dict)
            << "motionType " << name << " (a flight controller of the paper"
            << " authors' code) is not a motion type of flapFoam, where a"
            << " controller entry sets the motions' parameters"
            << (
                   name.starts_with("midStartControl_xzth")
                 ? " (flapfoam authors_control <this file> writes"
                   " the equivalent imposedMotion and controller entries)"
                 : " (docs/control.md)"
               )
            << ": must be one of " << motionTypeNames.sortedToc()
            << exit(FatalIOError);
    }

    return
        readChoice(dict, "motionType", motionTypeNames, motionType::standard);
}


Foam::scalar Foam::imposedMotions::wangParametrization::amplitudeSign
(
    const motionType type
)
{
    return type == motionType::standard ? 1 : -1;
}


Foam::imposedMotions::wangWaveform
Foam::imposedMotions::wangParametrization::readPhi
(
    const dictionary& dict,
    const motionType type
)
{
    const scalar A = dict.get<scalar>("Aphi");
    const scalar f = readAllowed(dict, "fphi", allowed::above(0.0));
    const scalar K =
        wangWaveform::readK(dict, "Kphi", wangWaveform::shape::flapping);

    // standard: A asin(K cos(theta))/asin(K);
    // midStart: -A asin(K sin(theta))/asin(K), sin = cos(theta - pi/2)
    const scalar phase =
        type == motionType::standard ? 0 : -constant::mathematical::piByTwo;

    return wangWaveform
    (
        {wangWaveform::shape::flapping, amplitudeSign(type)*A, f, K, phase, 0}
    );
}


Foam::imposedMotions::wangWaveform
Foam::imposedMotions::wangParametrization::readAlpha
(
    const dictionary& dict,
    const motionType type
)
{
    const scalar A = dict.get<scalar>("Aalpha");
    const scalar f = readAllowed(dict, "falpha", allowed::above(0.0));
    const scalar K =
        wangWaveform::readK(dict, "Kalpha", wangWaveform::shape::pitching);

    // standard: A tanh(K sin(theta))/tanh(K);
    // midStart: A - A tanh(K cos(theta))/tanh(K), cos = sin(theta + pi/2)
    const bool standard = type == motionType::standard;
    const scalar phase = standard ? 0 : constant::mathematical::piByTwo;
    const scalar offset = standard ? 0 : A;

    return wangWaveform
    (
        {
            wangWaveform::shape::pitching,
            amplitudeSign(type)*A,
            f,
            K,
            phase,
            offset
        }
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::imposedMotions::wangParametrization::wangParametrization
(
    const word& name,
    const dictionary& dict
)
:
    imposedMotion(name, dict, readJointList(dict)),
    motionType_(readMotionType(dict)),
    phi_(readPhi(dict, motionType_)),
    alpha_(readAlpha(dict, motionType_))
{}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::imposedMotions::wangParametrization::evaluate
(
    const label i,
    const scalar t,
    scalar& q,
    scalar& qDot,
    scalar& qDdot
) const
{
    if (i % 2)
    {
        alpha_.evaluate(t, q, qDot, qDdot);
    }
    else
    {
        phi_.evaluate(t, q, qDot, qDdot);
    }

    // midStart_2wings: the second wing flaps mirrored (the authors' -phi)
    if (i == 2)
    {
        q = -q;
        qDot = -qDot;
        qDdot = -qDdot;
    }
}


void Foam::imposedMotions::wangParametrization::write(Ostream& os) const
{
    imposedMotion::write(os);

    os.writeEntry("motionType", motionTypeNames[motionType_]);
    const scalar sign = amplitudeSign(motionType_);

    os.writeEntry("Aphi", sign*phi_.amplitude());
    os.writeEntry("fphi", phi_.frequency());
    os.writeEntry("Kphi", phi_.K());
    os.writeEntry("Aalpha", sign*alpha_.amplitude());
    os.writeEntry("falpha", alpha_.frequency());
    os.writeEntry("Kalpha", alpha_.K());
}


// ************************************************************************* //
