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

#include "quasiSteady.H"
#include "Tuple2.H"
#include "dictionaryKeys.H"
#include "dictionaryRead.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace wingAerodynamicsModels
{
    defineTypeNameAndDebug(quasiSteady, 0);
    addToRunTimeSelectionTable(wingAerodynamics, quasiSteady, dictionary);
}
}


const Foam::Enum
<
    Foam::wingAerodynamicsModels::quasiSteady::distributionType
>
Foam::wingAerodynamicsModels::quasiSteady::distributionNames
({
    { distributionType::semiElliptic, "semiElliptic" },
    { distributionType::table, "table" }
});


const Foam::wordList& Foam::wingAerodynamicsModels::quasiSteady::keys()
{
    static const wordList k
    ({
        "type", "body", "root", "span", "chord", "length",
        "chordDistribution", "meanChord", "chords", "rho", "CL", "CD0",
        "CD1", "CoP0", "CoP1", "nStrips", "wind"
    });
    return k;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::dictionary& Foam::wingAerodynamicsModels::quasiSteady::checked
(
    const dictionary& dict
)
{
    dictionaryKeys(keys())
        .named(dictionaryKeys::pathOf(dict) + " (type quasiSteady)")
        .check(dict);
    return dict;
}


Foam::vector Foam::wingAerodynamicsModels::quasiSteady::readUnit
(
    const dictionary& dict,
    const word& key
)
{
    const vector v(dict.get<vector>(key));
    if (mag(mag(v) - 1) > 1e-6)
    {
        FatalIOErrorInFunction(dict)
            << key << ' ' << v << " has length " << mag(v)
            << ": a unit vector (length 1 within 1e-6) is required"
            << exit(FatalIOError);
    }
    return v/mag(v);
}


Foam::scalarField Foam::wingAerodynamicsModels::quasiSteady::chords
(
    const dictionary& dict,
    const scalarField& r,
    const scalar R
)
{
    const distributionType distribution
    (
        readChoice(dict, "chordDistribution", distributionNames)
    );
    const bool semiElliptic = distribution == distributionType::semiElliptic;
    const word other(semiElliptic ? "chords" : "meanChord");
    if (dict.found(other))
    {
        FatalIOErrorInFunction(dict)
            << other << " does not belong to chordDistribution "
            << distributionNames[distribution] << exit(FatalIOError);
    }

    if (semiElliptic)
    {
        const scalar cbar = readAllowed(dict, "meanChord", allowed::above(0.0));
        return (4*cbar/constant::mathematical::pi)*sqrt(1 - sqr(r/R));
    }

    const List<Tuple2<scalar, scalar>> table
    (
        dict.get<List<Tuple2<scalar, scalar>>>("chords")
    );
    bool ok = table.size() >= 2 && table.first().first() <= 0
        && table.last().first() >= R;
    for (label i = 0; ok && i < table.size(); ++i)
    {
        ok = table[i].second() >= 0
          && (i == 0 || table[i].first() > table[i - 1].first());
    }
    if (!ok)
    {
        FatalIOErrorInFunction(dict)
            << "chords " << table << ": at least two (r c) pairs, r rising"
            << " and covering 0 to length " << R << ", c >= 0, are required"
            << exit(FatalIOError);
    }

    scalarField c(r.size());
    label j = 0;
    forAll(r, k)
    {
        while (table[j + 1].first() < r[k])
        {
            ++j;
        }
        const scalar f =
            (r[k] - table[j].first())
           /(table[j + 1].first() - table[j].first());
        c[k] = (1 - f)*table[j].second() + f*table[j + 1].second();
    }
    return c;
}


Foam::vector Foam::wingAerodynamicsModels::quasiSteady::stripForce
(
    const vector& uPerp,
    const vector& s,
    const vector& c,
    const scalar area,
    scalar& alpha
) const
{
    const scalar magU = mag(uPerp);
    alpha = 0;
    if (magU < 1e-12)
    {
        return Zero;
    }
    const vector eD(uPerp/magU);
    alpha = acos(min(scalar(1), mag(eD & c)));

    // Lift normal to the span and the flow, on the side the air flows
    // through the plate (the plate's normal n = c x s)
    const vector n(c ^ s);
    vector eL(s ^ eD);
    eL /= mag(eL);
    if ((eL & n)*(uPerp & n) < 0)
    {
        eL = -eL;
    }

    const scalar CL = CL_*sin(2*alpha);
    const scalar CD = CD0_ + CD1_*(1 - cos(2*alpha));
    return (0.5*rho_*sqr(magU)*area)*(CL*eL + CD*eD);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wingAerodynamicsModels::quasiSteady::quasiSteady
(
    const word& name,
    const RBD::rigidBodyModel& model,
    const dictionary& dict
)
:
    wingAerodynamics(name, model, checked(dict)),
    span_(readUnit(dict, "span")),
    chord_(readUnit(dict, "chord")),
    rho_(readAllowed(dict, "rho", allowed::above(0.0))),
    CL_(dict.getOrDefault<scalar>("CL", 1.2)),
    CD0_(dict.getOrDefault<scalar>("CD0", 0.4)),
    CD1_(dict.getOrDefault<scalar>("CD1", 1.0)),
    CoP0_(dict.getOrDefault<scalar>("CoP0", 0)),
    CoP1_(dict.getOrDefault<scalar>("CoP1", 0)),
    wind_(dict.getOrDefault<vector>("wind", Zero))
{
    if (mag(span_ & chord_) > 1e-6)
    {
        FatalIOErrorInFunction(dict)
            << "span " << span_ << " and chord " << chord_
            << " are not normal to each other (span.chord "
            << (span_ & chord_) << "): |span.chord| <= 1e-6 is required"
            << exit(FatalIOError);
    }
    const scalar R = readAllowed(dict, "length", allowed::above(0.0));
    const label N =
        readAllowed(dict, "nStrips", 40, allowed::atLeast<label>(1));

    scalarField r(N);
    forAll(r, k)
    {
        r[k] = (k + 0.5)*R/N;
    }
    chordLengths_ = chords(dict, r, R);
    areas_ = chordLengths_*(R/N);
    points_ = dict.get<vector>("root") + r*span_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::spatialVector Foam::wingAerodynamicsModels::quasiSteady::load
(
    const RBD::rigidBodyModel& model
) const
{
    // X0 maps global to body coordinates
    const spatialTransform X0(model.X0(bodyID_));
    const spatialTransform toGlobal(X0.inv());
    const vector s(X0.E().T() & span_);
    const vector c(X0.E().T() & chord_);

    vector force(Zero);
    vector moment(Zero);
    forAll(points_, k)
    {
        const vector u(wind_ - model.v(bodyID_, points_[k]).l());
        scalar alpha;
        const vector dF(stripForce(u - (u & s)*s, s, c, areas_[k], alpha));

        // At the chordwise centre of pressure, from the pitch axis
        const scalar d =
            (CoP0_ + CoP1_*alpha/constant::mathematical::piByTwo)
           *chordLengths_[k];
        force += dF;
        moment += (toGlobal.transformPoint(points_[k]) + d*c) ^ dF;
    }
    return spatialVector(moment, force);
}


// ************************************************************************* //
