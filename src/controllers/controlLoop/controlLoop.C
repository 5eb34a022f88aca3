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

#include "controlLoop.H"
#include "dictionaryKeys.H"
#include "dictionaryRead.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::controlLoop::saturationType>
Foam::controlLoop::saturationNames
({
    { saturationType::tanh, "tanh" },
    { saturationType::linear, "linear" }
});


const Foam::wordList& Foam::controlLoop::keys()
{
    static const wordList k
    ({
        "entry", "parameter", "saturation", "min", "max", "bias", "terms"
    });
    return k;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::controlLoop::controlLoop
(
    const RBD::rigidBodyModel& model,
    const imposedMotionList& motions,
    const dictionary& dict
)
:
    name_(dictionaryKeys(keys()).checked(dict).dictName()),
    entry_(dict.get<word>("entry")),
    parameter_(dict.get<word>("parameter")),
    saturation_(readChoice(dict, "saturation", saturationNames)),
    min_(dict.get<scalar>("min")),
    max_(dict.get<scalar>("max")),
    bias_(dict.getOrDefault<scalar>("bias", 0)),
    terms_(),
    u_(0),
    output_(0),
    clipped_(false)
{
    const imposedMotion& motion = motions.current(dict, "entry");
    const wordList allowed(motion.controlKeys());
    if (!allowed.found(parameter_))
    {
        FatalIOErrorInFunction(dict)
            << "parameter " << parameter_ << " of " << dict.name()
            << ": a controller may set of entry " << entry_ << " (type "
            << motion.type() << ") " << flatOutput(allowed)
            << exit(FatalIOError);
    }

    if (!(min_ < max_))
    {
        FatalIOErrorInFunction(dict)
            << "min " << min_ << " and max " << max_ << " of " << dict.name()
            << ": min < max is required" << exit(FatalIOError);
    }

    const dictionary& termsDict = dict.subDict("terms");
    for (const Foam::entry& e : termsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(termsDict)
                << "terms of " << dict.name() << ": '" << e.keyword()
                << "' is not a sub-dictionary (one per measured error)"
                << exit(FatalIOError);
        }
        terms_.append(new controlTerm(model, e.dict()));
    }

    if (terms_.empty())
    {
        FatalIOErrorInFunction(termsDict)
            << "terms of " << dict.name() << " is empty: at least one"
            << " measured error is needed" << exit(FatalIOError);
    }

    output_ = motions.get(entry_, parameter_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::controlLoop::saturate(const scalar u) const
{
    if (saturation_ == saturationType::tanh)
    {
        return min_ + (max_ - min_)*0.5*(1 + Foam::tanh(u));
    }

    return Foam::min(Foam::max(u, min_), max_);
}


void Foam::controlLoop::start()
{
    for (controlTerm& term : terms_)
    {
        term.start();
    }
}


Foam::scalar Foam::controlLoop::update(const scalar t, const scalar dt)
{
    const bool freeze = clipped_;

    u_ = bias_;
    for (controlTerm& term : terms_)
    {
        u_ += term.update(t, dt, freeze);
    }

    output_ = saturate(u_);
    clipped_ =
        saturation_ == saturationType::linear
     && (u_ < min_ || u_ > max_);

    return output_;
}


Foam::wordList Foam::controlLoop::recordNames() const
{
    wordList names({name_ + ".u", name_ + ".output"});
    for (const controlTerm& term : terms_)
    {
        const word prefix(name_ + "." + term.name());
        names.append(prefix + ".error");
        names.append(prefix + ".errorRate");
        names.append(prefix + ".integral");
    }
    return names;
}


Foam::scalarList Foam::controlLoop::record() const
{
    scalarList values({u_, output_});
    for (const controlTerm& term : terms_)
    {
        values.append(term.error());
        values.append(term.errorRate());
        values.append(term.integral());
    }
    return values;
}


void Foam::controlLoop::writeState(dictionary& dict) const
{
    dict.add("u", u_);
    dict.add("output", output_);
    dict.add("clipped", clipped_);

    for (const controlTerm& term : terms_)
    {
        dictionary termDict;
        term.writeState(termDict);
        dict.add(term.name(), termDict);
    }
}


void Foam::controlLoop::readState(const dictionary& dict)
{
    u_ = dict.get<scalar>("u");
    output_ = dict.get<scalar>("output");
    clipped_ = dict.get<bool>("clipped");

    for (controlTerm& term : terms_)
    {
        term.readState(dict.subDict(term.name()));
    }
}


void Foam::controlLoop::write(Ostream& os) const
{
    os.writeEntry("entry", entry_);
    os.writeEntry("parameter", parameter_);
    os.writeEntry("saturation", saturationNames[saturation_]);
    os.writeEntry("min", min_);
    os.writeEntry("max", max_);
    os.writeEntry("bias", bias_);
    os.beginBlock("terms");
    for (const controlTerm& term : terms_)
    {
        os.beginBlock(term.name());
        term.write(os);
        os.endBlock();
    }
    os.endBlock();
}


// ************************************************************************* //
