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

#include "fourier.H"
#include "dictionaryRead.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace imposedMotions
{
    defineTypeNameAndDebug(fourier, 0);
    addToRunTimeSelectionTable(imposedMotion, fourier, dictionary);

    // The keys of the Usage table besides type
    static const imposedMotion::addTypeKeys addfourierKeys_
    (
        imposedMotions::fourier::typeName,
        {
            "joint",
            wordList({"frequency", "a0", "a", "b"}),
            wordList(),
            nullptr         // nothing to check first
        }
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::imposedMotions::fourier::fourier
(
    const word& name,
    const dictionary& dict
)
:
    imposedMotion(name, dict),
    frequency_(readAllowed(dict, "frequency", allowed::above(0.0))),
    omega_(constant::mathematical::twoPi*frequency_),
    a0_(dict.getOrDefault<scalar>("a0", 0)),
    a_(),
    b_()
{
    const bool haveA = dict.readIfPresent("a", a_);
    const bool haveB = dict.readIfPresent("b", b_);

    if (!haveA && !haveB)
    {
        FatalIOErrorInFunction(dict)
            << "Neither entry 'a' nor entry 'b' found: give the cosine"
            << " coefficients 'a' (a_1 .. a_N), the sine coefficients 'b'"
            << " (b_1 .. b_N), or both" << nl
            << exit(FatalIOError);
    }

    if (haveA && haveB && a_.size() != b_.size())
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'a' (" << a_.size() << " coefficients) and 'b' ("
            << b_.size() << " coefficients) must have the same length"
            << nl << exit(FatalIOError);
    }

    // The one left out is zeros
    if (!haveA)
    {
        a_.setSize(b_.size(), Zero);
    }
    if (!haveB)
    {
        b_.setSize(a_.size(), Zero);
    }

    if (a_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'a' and 'b' are empty: at least one coefficient"
            << " (N >= 1) is needed" << nl
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::imposedMotions::fourier::evaluate
(
    const label,
    const scalar t,
    scalar& q,
    scalar& qDot,
    scalar& qDdot
) const
{
    // First harmonic c1 = cos(omega t), s1 = sin(omega t)
    const scalar theta = omega_*t;
    const scalar c1 = ::cos(theta);
    const scalar s1 = ::sin(theta);

    q = a0_;
    qDot = 0;
    qDdot = 0;

    // cn = cos(n omega t), sn = sin(n omega t), starting at n = 1
    scalar cn = c1;
    scalar sn = s1;

    forAll(a_, k)
    {
        const scalar nOmega = (k + 1)*omega_;

        // a_n cos + b_n sin, and its derivative / (n omega)
        const scalar harmonic = a_[k]*cn + b_[k]*sn;
        const scalar dHarmonic = -a_[k]*sn + b_[k]*cn;

        q += harmonic;
        qDot += nOmega*dHarmonic;
        qDdot -= nOmega*nOmega*harmonic;

        // Angle sum: cos((n+1)x) = cos(nx) cos(x) - sin(nx) sin(x),
        //            sin((n+1)x) = sin(nx) cos(x) + cos(nx) sin(x)
        const scalar cNext = cn*c1 - sn*s1;
        sn = sn*c1 + cn*s1;
        cn = cNext;
    }
}


void Foam::imposedMotions::fourier::write(Ostream& os) const
{
    imposedMotion::write(os);

    os.writeEntry("frequency", frequency_);
    os.writeEntry("a0", a0_);
    os.writeEntry("a", a_);
    os.writeEntry("b", b_);
}


// ************************************************************************* //
