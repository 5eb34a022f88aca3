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

#include "controlTerm.H"
#include "dictionaryKeys.H"
#include "dictionaryRead.H"
#include "treeBody.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::controlTerm::quantityType>
Foam::controlTerm::quantityNames
({
    { quantityType::position, "position" },
    { quantityType::velocity, "velocity" },
    { quantityType::orientation, "orientation" },
    { quantityType::angularVelocity, "angularVelocity" }
});


const Foam::Enum<Foam::controlTerm::derivativeType>
Foam::controlTerm::derivativeNames
({
    { derivativeType::state, "state" },
    { derivativeType::mean, "mean" }
});


const Foam::Enum<Foam::vector::components>
Foam::controlTerm::componentNames
({
    { vector::X, "x" },
    { vector::Y, "y" },
    { vector::Z, "z" }
});


const Foam::wordList& Foam::controlTerm::keys()
{
    static const wordList k
    ({
        "body", "quantity", "component", "setPoint", "rateSetPoint",
        "derivative", "Kp", "Ki", "Kd"
    });
    return k;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::controlTerm::measure() const
{
    const spatialTransform& X0 = model_.X0(bodyID_);
    const vector c(model_.I(bodyID_).c());

    switch (quantity_)
    {
        case quantityType::position:
        {
            return X0.inv().transformPoint(c)[component_];
        }
        case quantityType::velocity:
        {
            return model_.v(bodyID_, c).l()[component_];
        }
        case quantityType::angularVelocity:
        {
            return model_.v(bodyID_, c).w()[component_];
        }
        case quantityType::orientation:
        {
            // Body-to-global rotation, Tait-Bryan z-y'-x''
            const tensor R(X0.E().T());
            if (component_ == vector::X)
            {
                return atan2(R.zy(), R.zz());
            }
            if (component_ == vector::Y)
            {
                return asin(max(-1.0, min(1.0, -R.zx())));
            }
            return atan2(R.yx(), R.xx());
        }
    }

    return 0;
}


Foam::scalar Foam::controlTerm::measureRate() const
{
    const spatialVector v(model_.v(bodyID_, model_.I(bodyID_).c()));

    return
        quantity_ == quantityType::position
      ? v.l()[component_]
      : v.w()[component_];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::controlTerm::controlTerm
(
    const RBD::rigidBodyModel& model,
    const dictionary& dict
)
:
    name_(dictionaryKeys(keys()).checked(dict).dictName()),
    model_(model),
    body_(dict.get<word>("body")),
    bodyID_(treeBodyID(model, body_, dict)),
    quantity_(readChoice(dict, "quantity", quantityNames)),
    component_(readChoice(dict, "component", componentNames)),
    setPoint_(Function1<scalar>::New("setPoint", dict)),
    rateSetPoint_(nullptr),
    derivative_
    (
        readChoice(dict, "derivative", derivativeNames, derivativeType::state)
    ),
    Kp_(dict.getOrDefault<scalar>("Kp", 0)),
    Ki_(dict.getOrDefault<scalar>("Ki", 0)),
    Kd_(dict.getOrDefault<scalar>("Kd", 0)),
    e_(0),
    eDot_(0),
    integral_(0),
    previous_(0)
{
    const bool hasRate =
        quantity_ == quantityType::position
     || quantity_ == quantityType::orientation;

    if (Kd_ != 0 && !hasRate && derivative_ == derivativeType::state)
    {
        FatalIOErrorInFunction(dict)
            << "Kd " << Kd_ << " of " << dict.name() << ": the quantity "
            << quantityNames[quantity_] << " has no rate in the state (Kd is"
            << " allowed for position and orientation only, or with"
            << " derivative mean)" << exit(FatalIOError);
    }

    if (dict.found("rateSetPoint", keyType::LITERAL))
    {
        rateSetPoint_ = Function1<scalar>::New("rateSetPoint", dict);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::controlTerm::update
(
    const scalar t,
    const scalar dt,
    const bool freeze
)
{
    const scalar m = measure();
    const scalar rateSetPoint =
        rateSetPoint_.valid() ? rateSetPoint_->value(t) : 0;

    e_ = m - setPoint_->value(t);

    eDot_ = 0;
    if (derivative_ == derivativeType::mean)
    {
        eDot_ = dt > 0 ? (m - previous_)/dt - rateSetPoint : 0;
    }
    else if
    (
        quantity_ == quantityType::position
     || quantity_ == quantityType::orientation
    )
    {
        eDot_ = measureRate() - rateSetPoint;
    }
    previous_ = m;

    if (!freeze)
    {
        integral_ += e_*dt;
    }

    return Kp_*e_ + Ki_*integral_ + Kd_*eDot_;
}


void Foam::controlTerm::writeState(dictionary& dict) const
{
    dict.add("error", e_);
    dict.add("errorRate", eDot_);
    dict.add("integral", integral_);
    dict.add("previous", previous_);
}


void Foam::controlTerm::readState(const dictionary& dict)
{
    e_ = dict.get<scalar>("error");
    eDot_ = dict.get<scalar>("errorRate");
    integral_ = dict.get<scalar>("integral");
    previous_ = dict.get<scalar>("previous");
}


void Foam::controlTerm::write(Ostream& os) const
{
    os.writeEntry("body", body_);
    os.writeEntry("quantity", quantityNames[quantity_]);
    os.writeEntry("component", word(vector::componentNames[component_]));
    setPoint_->writeData(os);
    if (rateSetPoint_.valid())
    {
        rateSetPoint_->writeData(os);
    }
    os.writeEntry("derivative", derivativeNames[derivative_]);
    os.writeEntry("Kp", Kp_);
    os.writeEntry("Ki", Ki_);
    os.writeEntry("Kd", Kd_);
}


// ************************************************************************* //
