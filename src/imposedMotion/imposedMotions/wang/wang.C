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

#include "wang.H"
#include "dictionaryRead.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace imposedMotions
{
    defineTypeNameAndDebug(wang, 0);
    addToRunTimeSelectionTable(imposedMotion, wang, dictionary);

    // The keys of the Usage table besides type
    static const imposedMotion::addTypeKeys addwangKeys_
    (
        imposedMotions::wang::typeName,
        {
            "joint",
            wordList
            ({
                "waveform", "amplitude", "frequency", "K", "phase", "offset"
            }),
            wordList(),
            nullptr         // nothing to check first
        }
    );
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::imposedMotions::wangWaveform
Foam::imposedMotions::wang::readWaveform(const dictionary& dict)
{
    const wangWaveform::shape waveform
    (
        readChoice(dict, "waveform", wangWaveform::shapeNames)
    );

    const scalar amplitude = dict.get<scalar>("amplitude");
    const scalar frequency =
        readAllowed(dict, "frequency", allowed::above(0.0));
    const scalar K = wangWaveform::readK(dict, "K", waveform);

    return wangWaveform
    (
        {
            waveform,
            amplitude,
            frequency,
            K,
            dict.getOrDefault<scalar>("phase", 0),
            dict.getOrDefault<scalar>("offset", 0)
        }
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::imposedMotions::wang::wang
(
    const word& name,
    const dictionary& dict
)
:
    imposedMotion(name, dict),
    waveform_(readWaveform(dict))
{}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::imposedMotions::wang::evaluate
(
    const label,
    const scalar t,
    scalar& q,
    scalar& qDot,
    scalar& qDdot
) const
{
    waveform_.evaluate(t, q, qDot, qDdot);
}


void Foam::imposedMotions::wang::write(Ostream& os) const
{
    imposedMotion::write(os);

    os.writeEntry
    (
        "waveform",
        wangWaveform::shapeNames[waveform_.waveform()]
    );
    os.writeEntry("amplitude", waveform_.amplitude());
    os.writeEntry("frequency", waveform_.frequency());
    os.writeEntry("K", waveform_.K());
    os.writeEntry("phase", waveform_.phase());
    os.writeEntry("offset", waveform_.offset());
}


// ************************************************************************* //
