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

#include "wangWaveform.H"
#include "dictionaryRead.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::imposedMotions::wangWaveform::shape>
Foam::imposedMotions::wangWaveform::shapeNames
({
    { shape::flapping, "flapping" },
    { shape::pitching, "pitching" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::imposedMotions::wangWaveform::wangWaveform(const parameters& p)
:
    p_(p),
    omega_(constant::mathematical::twoPi*p.frequency),
    S_
    (
        p.waveform == shape::flapping
      ? p.amplitude/::asin(p.K)
      : p.amplitude/::tanh(p.K)
    )
{}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::imposedMotions::wangWaveform::readK
(
    const dictionary& dict,
    const word& key,
    const shape waveform
)
{
    // Flapping asin(K cos(theta))/asin(K) needs 0 < K < 1; pitching
    // tanh(K sin(theta))/tanh(K) needs K > 0
    return readAllowed
    (
        dict,
        key,
        waveform == shape::flapping
      ? allowed::open(0.0, 1.0).noting("the flapping waveform")
      : allowed::above(0.0).noting("the pitching waveform")
    );
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::imposedMotions::wangWaveform::evaluate
(
    const scalar t,
    scalar& q,
    scalar& qDot,
    scalar& qDdot
) const
{
    const scalar theta = omega_*t + p_.phase;
    const scalar c = ::cos(theta);
    const scalar s = ::sin(theta);

    if (p_.waveform == shape::flapping)
    {
        // u = K cos(theta), u' = -K omega sin(theta), u'' = -omega^2 u
        const scalar u = p_.K*c;
        const scalar du = -p_.K*omega_*s;
        const scalar ddu = -omega_*omega_*u;

        // 1 - u^2 >= 1 - K^2 > 0
        const scalar oneMinusU2 = 1 - u*u;
        const scalar invRoot = 1/::sqrt(oneMinusU2);

        // q = q_0 + S asin(u)
        q = p_.offset + S_*::asin(u);

        // qDot = S u'/sqrt(1 - u^2)
        qDot = S_*du*invRoot;

        // qDdot = S/sqrt(1 - u^2) (u'' + u u'^2/(1 - u^2))
        qDdot = S_*invRoot*(ddu + u*du*du/oneMinusU2);
    }
    else
    {
        // v = K sin(theta), v' = K omega cos(theta), v'' = -omega^2 v
        const scalar v = p_.K*s;
        const scalar dv = p_.K*omega_*c;
        const scalar ddv = -omega_*omega_*v;

        // sech^2 from cosh, not 1 - tanh^2: accurate where tanh(v) ~ 1
        // (large K); cosh overflowing to inf gives sech^2 = 0, as it should
        const scalar th = ::tanh(v);
        const scalar sech = 1/::cosh(v);
        const scalar sech2 = sech*sech;

        // q = q_0 + S tanh(v)
        q = p_.offset + S_*th;

        // qDot = S v' sech^2(v)
        qDot = S_*dv*sech2;

        // qDdot = S sech^2(v) (v'' - 2 tanh(v) v'^2)
        qDdot = S_*sech2*(ddv - 2*th*dv*dv);
    }
}


// ************************************************************************* //
