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

#include "harmonic.H"
#include "dictionaryRead.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace imposedMotions
{
    defineTypeNameAndDebug(harmonic, 0);
    addToRunTimeSelectionTable(imposedMotion, harmonic, dictionary);

    // The keys of the Usage table besides type
    static const imposedMotion::addTypeKeys addharmonicKeys_
    (
        imposedMotions::harmonic::typeName,
        {
            "joint",
            wordList({"amplitude", "frequency", "phase", "offset"}),
            wordList(),
            nullptr         // nothing to check first
        }
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::imposedMotions::harmonic::harmonic
(
    const word& name,
    const dictionary& dict
)
:
    imposedMotion(name, dict),
    amplitude_(dict.get<scalar>("amplitude")),
    frequency_(readAllowed(dict, "frequency", allowed::above(0.0))),
    phase_(dict.getOrDefault<scalar>("phase", 0)),
    offset_(dict.getOrDefault<scalar>("offset", 0)),
    omega_(constant::mathematical::twoPi*frequency_)
{}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::imposedMotions::harmonic::evaluate
(
    const label,
    const scalar t,
    scalar& q,
    scalar& qDot,
    scalar& qDdot
) const
{
    const scalar theta = omega_*t + phase_;
    const scalar c = cos(theta);
    const scalar s = sin(theta);

    // q = q_0 + A cos(theta), theta = omega t + phi
    q = offset_ + amplitude_*c;

    // qDot = -A omega sin(theta)
    qDot = -amplitude_*omega_*s;

    // qDdot = -A omega^2 cos(theta)
    qDdot = -amplitude_*omega_*omega_*c;
}


void Foam::imposedMotions::harmonic::write(Ostream& os) const
{
    imposedMotion::write(os);

    os.writeEntry("amplitude", amplitude_);
    os.writeEntry("frequency", frequency_);
    os.writeEntry("phase", phase_);
    os.writeEntry("offset", offset_);
}


// ************************************************************************* //
