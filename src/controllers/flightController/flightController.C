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

#include "flightController.H"
#include "dictionaryKeys.H"
#include "dictionaryRead.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(flightController, 0);
    defineRunTimeSelectionTable(flightController, dictionary);
}


const Foam::Enum<Foam::flightController::updateType>
Foam::flightController::updateNames
({
    { updateType::cycle, "cycle" },
    { updateType::rate, "rate" }
});


const Foam::wordList& Foam::flightController::keys()
{
    static const wordList k
    ({
        "type", "update", "cycleOf", "rate", "blend", "log"
    });
    return k;
}


Foam::wordList Foam::flightController::allKeys(const wordList& typeKeys)
{
    wordList k(keys());
    k.append(typeKeys);
    return k;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::flightController::flightController
(
    const dictionary& dict,
    const RBD::rigidBodyModel& model,
    imposedMotionList& motions,
    const wordList& typeKeys
)
:
    allowedKeys_(allKeys(typeKeys)),
    update_
    (
        readChoice
        (
            dictionaryKeys(allowedKeys_).checked(dict),
            "update",
            updateNames
        )
    ),
    cycleOf_(),
    rate_(0),
    blend_(readAllowed(dict, "blend", 0.25, allowed::closed(0.0, 1.0))),
    log_(dict.getOrDefault<Switch>("log", true)),
    tLast_(0),
    tNext_(-1),
    nUpdates_(0),
    model_(model),
    motions_(motions)
{
    if (update_ == updateType::cycle)
    {
        cycleOf_ = dict.get<word>("cycleOf");
        const imposedMotion& m = motions_.current(dict, "cycleOf");
        if (m.frequencyKey().empty())
        {
            FatalIOErrorInFunction(dict)
                << "cycleOf " << cycleOf_ << " of " << dict.name()
                << ": its type " << m.type() << " has no frequency (use"
                << " harmonic, wang or fourier, or update rate)"
                << exit(FatalIOError);
        }
    }
    else
    {
        rate_ = readAllowed(dict, "rate", allowed::above(0.0));
    }
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

Foam::scalar Foam::flightController::period() const
{
    if (update_ == updateType::rate)
    {
        return 1/rate_;
    }

    const imposedMotion& m = motions_.blend(cycleOf_).current();
    return 1/motions_.get(cycleOf_, m.frequencyKey());
}


void Foam::flightController::set
(
    const word& entry,
    const word& parameter,
    scalar value,
    const scalar t
)
{
    Pstream::scatter(value);
    motions_.set(entry, parameter, value, t, blend_*period());
}


void Foam::flightController::update(const RBD::rigidBodyModelState& state)
{
    const scalar t = state.t();
    const scalar T = period();

    if (tNext_ < 0)
    {
        start();
        tLast_ = t;
        tNext_ = t + T;
    }

    // Due at the first step start at or after tNext (round-off of the
    // accumulated times allowed)
    if (!due(t))
    {
        return;
    }

    control(t, t - tLast_);
    ++nUpdates_;
    tLast_ = t;
    while (tNext_ <= t + 1e-9*T)
    {
        tNext_ += period();
    }

    if (log_)
    {
        Info<< type() << " controller update " << nUpdates_ << " at t = "
            << t << ':';
        log(Info);
        Info<< " (blend " << blend_*period() << " s, next at t = " << tNext_
            << ')' << endl;
    }
}


void Foam::flightController::writeState(dictionary& stateDict) const
{
    dictionary dict;
    dict.add("type", type());
    dict.add("tLast", tLast_);
    dict.add("tNext", tNext_);
    dict.add("nUpdates", nUpdates_);
    writeTypeState(dict);

    stateDict.set("controllerState", dict);
}


void Foam::flightController::readState(const dictionary& stateDict)
{
    const dictionary* dictPtr =
        stateDict.findDict("controllerState", keyType::LITERAL);

    if (!dictPtr)
    {
        return;     // the controller starts with this run
    }

    const dictionary& dict = *dictPtr;
    const word stateType(dict.get<word>("type"));
    if (stateType != type())
    {
        FatalIOErrorInFunction(dict)
            << "controllerState of type " << stateType << " but the"
            << " controller is of type " << type() << ": restart from a"
            << " state of the same controller, or remove controllerState"
            << " from " << stateDict.name() << " to start it afresh"
            << exit(FatalIOError);
    }

    tLast_ = dict.get<scalar>("tLast");
    tNext_ = dict.get<scalar>("tNext");
    nUpdates_ = dict.get<label>("nUpdates");
    readTypeState(dict);

    Info<< type() << " controller: restart after update " << nUpdates_
        << " (t = " << tLast_ << "), next at t = " << tNext_ << endl;
}


void Foam::flightController::write(Ostream& os) const
{
    os.writeEntry("type", type());
    os.writeEntry("update", updateNames[update_]);
    if (update_ == updateType::cycle)
    {
        os.writeEntry("cycleOf", cycleOf_);
    }
    else
    {
        os.writeEntry("rate", rate_);
    }
    os.writeEntry("blend", blend_);
    os.writeEntry("log", log_);
}


// ************************************************************************* //
