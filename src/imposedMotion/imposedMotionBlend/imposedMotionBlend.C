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

#include "imposedMotionBlend.H"
#include "dictionaryRead.H"
#include "primitiveEntry.H"
#include "StringStream.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::entry* Foam::imposedMotionBlend::scalarEntry
(
    const word& key,
    const scalar value
)
{
    return new primitiveEntry(key, token(value));
}


void Foam::imposedMotionBlend::checkKey(const word& key) const
{
    const wordList allowed(current().controlKeys());

    if (!allowed.found(key))
    {
        OStringStream names;
        for (const word& k : allowed)
        {
            names << ' ' << k;
        }

        FatalErrorInFunction
            << "Unknown parameter '" << key << "' of imposedMotion entry '"
            << current().name() << "' (type " << current().type()
            << "): a controller may set"
            << (allowed.size() ? names.str().c_str() : " none") << nl
            << exit(FatalError);
    }
}


void Foam::imposedMotionBlend::evaluateStage
(
    const label k,
    const label i,
    const scalar t,
    jointState& s
) const
{
    if (k == 0 || t >= t0_[k] + blendTime_[k])
    {
        motions_[k].evaluate(i, t + shift_[k], s.q, s.qDot, s.qDdot);
        return;
    }

    if (t <= t0_[k])
    {
        evaluateStage(k - 1, i, t, s);
        return;
    }

    // Inside the blend (Tb > 0 here): old and new motion
    jointState old, now;
    evaluateStage(k - 1, i, t, old);
    motions_[k].evaluate(i, t + shift_[k], now.q, now.qDot, now.qDdot);

    // Quintic smoothstep s0 = s(x), x = (t - t0)/Tb, and its time
    // derivatives s1, s2
    const scalar Tb = blendTime_[k];
    const scalar x = (t - t0_[k])/Tb;
    const scalar s0 = x*x*x*(10 + x*(-15 + 6*x));
    const scalar s1 = 30*sqr(x*(1 - x))/Tb;
    const scalar s2 = 60*x*(1 - x)*(1 - 2*x)/sqr(Tb);

    const scalar dq = now.q - old.q;
    const scalar dqDot = now.qDot - old.qDot;

    s.qDdot =
        old.qDdot + s0*(now.qDdot - old.qDdot) + 2*s1*dqDot + s2*dq;
    s.qDot = old.qDot + s0*dqDot + s1*dq;
    s.q = old.q + s0*dq;
}


void Foam::imposedMotionBlend::prune(const scalar t0)
{
    label first = 0;
    for (label k = motions_.size() - 1; k > 0; --k)
    {
        if (t0_[k] + blendTime_[k] <= t0)
        {
            first = k;
            break;
        }
    }

    if (first == 0)
    {
        return;
    }

    const label n = motions_.size() - first;
    PtrList<imposedMotion> kept(n);
    forAll(kept, j)
    {
        kept.set(j, motions_.set(first + j, nullptr));
    }
    motions_.transfer(kept);

    shift_ = scalarList(SubList<scalar>(shift_, n, first));
    t0_ = scalarList(SubList<scalar>(t0_, n, first));
    blendTime_ = scalarList(SubList<scalar>(blendTime_, n, first));
}


void Foam::imposedMotionBlend::append
(
    autoPtr<imposedMotion>&& motion,
    const scalar shift,
    const scalar t0,
    const scalar blendTime
)
{
    motions_.append(std::move(motion));
    shift_.append(shift);
    t0_.append(t0);
    blendTime_.append(blendTime);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::imposedMotionBlend::imposedMotionBlend(const imposedMotion& motion)
:
    motions_(),
    shift_(),
    t0_(),
    blendTime_()
{
    // The keys the type ignores are left out, so that their warning is not
    // repeated at every change
    dictionary parameters(motion.dict());
    for (const word& key : motion.ignoredKeys())
    {
        parameters.remove(key);
    }

    append(imposedMotion::New(motion.name(), parameters), 0, -GREAT, 0);
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

bool Foam::imposedMotionBlend::blending(const scalar t) const
{
    for (label k = 1; k < motions_.size(); ++k)
    {
        if (t > t0_[k] && t < t0_[k] + blendTime_[k])
        {
            return true;
        }
    }
    return false;
}


Foam::scalar Foam::imposedMotionBlend::get(const word& key) const
{
    checkKey(key);

    // The optional control keys all default to 0
    return current().dict().getOrDefault<scalar>(key, 0);
}


void Foam::imposedMotionBlend::set
(
    const word& key,
    const scalar value,
    const scalar t0,
    const scalar blendTime
)
{
    const scalar oldValue = get(key);
    const word& name = current().name();

    if (!(blendTime >= 0))
    {
        FatalErrorInFunction
            << "Blend time " << blendTime << " of parameter '" << key
            << "' of imposedMotion entry '" << name
            << "' is out of range: it must be >= 0" << nl
            << exit(FatalError);
    }

    if (t0 < t0_.last())
    {
        FatalErrorInFunction
            << "Change of parameter '" << key << "' of imposedMotion entry '"
            << name << "' at t0 = " << t0 << " before the last change, at "
            << t0_.last() << ": changes must come in time order" << nl
            << exit(FatalError);
    }

    prune(t0);

    dictionary parameters(current().dict());
    parameters.set(scalarEntry(key, value));

    // Checks the value as the type checks its dictionary
    autoPtr<imposedMotion> motion(imposedMotion::New(name, parameters));

    // Same phase at t0: f_new (t0 + delta_new) = f_old (t0 + delta_old)
    scalar shift = shift_.last();
    if (key == motion->frequencyKey())
    {
        shift = oldValue*(t0 + shift)/value - t0;
    }

    append(std::move(motion), shift, t0, blendTime);
}


void Foam::imposedMotionBlend::evaluate
(
    const label i,
    const scalar t,
    scalar& q,
    scalar& qDot,
    scalar& qDdot
) const
{
    jointState s;
    evaluateStage(motions_.size() - 1, i, t, s);
    q = s.q;
    qDot = s.qDot;
    qDdot = s.qDdot;
}


void Foam::imposedMotionBlend::writeState(dictionary& dict) const
{
    dict.set("nStages", motions_.size());

    forAll(motions_, k)
    {
        dictionary stage;
        if (k > 0)
        {
            stage.add(scalarEntry("t0", t0_[k]));
            stage.add(scalarEntry("blendTime", blendTime_[k]));
        }
        stage.add(scalarEntry("shift", shift_[k]));
        stage.add("parameters", motions_[k].dict());

        dict.set(word("stage" + Foam::name(k)), stage);
    }
}


void Foam::imposedMotionBlend::reportChanged
(
    const dictionary& given,
    const dictionary& state
) const
{
    // The parameters in effect at the restart (the last stage) against the
    // dictionary's entry: a controller's changes, or an edited dictionary
    const dictionary now(current().dict());
    const auto text = [](const entry& e)
    {
        OStringStream os;
        os.precision(17);
        for (const token& tok : e.stream())
        {
            os << ' ' << tok;
        }
        return os.str();
    };
    OStringStream changed;
    for (const entry& e : now)
    {
        const entry* g = given.findEntry(e.keyword(), keyType::LITERAL);
        if (!g || text(e) != text(*g))
        {
            changed << ' ' << e.keyword() << text(e).c_str()
                << " (dictionary" << (g ? text(*g).c_str() : " none")
                << ')';
        }
    }
    if (!changed.str().empty())
    {
        Info<< "imposedMotion entry " << current().name() << ": the state "
            << state.name() << " (as the run left it) replaces the"
            << " dictionary's parameters:" << changed.str().c_str() << nl;
    }
}


void Foam::imposedMotionBlend::readState(const dictionary& dict)
{
    const label nStages =
        readAllowed(dict, "nStages", allowed::atLeast<label>(1));

    const word name(current().name());
    const word type(current().type());
    const labelList joints(current().joints());
    const dictionary given(current().dict());

    motions_.clear();
    shift_.clear();
    t0_.clear();
    blendTime_.clear();

    for (label k = 0; k < nStages; ++k)
    {
        const dictionary& stage = dict.subDict(word("stage" + Foam::name(k)));

        const dictionary& parameters = stage.subDict("parameters");

        append
        (
            imposedMotion::New(name, parameters),
            stage.get<scalar>("shift"),
            k ? stage.get<scalar>("t0") : -GREAT,
            k ? stage.get<scalar>("blendTime") : 0
        );

        if (current().type() != type || current().joints() != joints)
        {
            FatalIOErrorInFunction(parameters)
                << "State of imposedMotion entry '" << name << "': type "
                << current().type() << " joints " << current().joints()
                << " where the model has type " << type << " joints "
                << joints << ": the state belongs to another model" << nl
                << exit(FatalIOError);
        }
    }

    reportChanged(given, dict);
}


// ************************************************************************* //
