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

#include "PID.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace flightControllers
{
    defineTypeNameAndDebug(PID, 0);
    addToRunTimeSelectionTable(flightController, PID, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::flightControllers::PID::PID
(
    const dictionary& dict,
    const RBD::rigidBodyModel& model,
    imposedMotionList& motions
)
:
    flightController(dict, model, motions, wordList({"loops"})),
    loops_()
{
    const dictionary& loopsDict = dict.subDict("loops");
    wordList outputs;
    for (const entry& e : loopsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(loopsDict)
                << "loops of " << dict.name() << ": '" << e.keyword()
                << "' is not a sub-dictionary (one per controlled parameter)"
                << exit(FatalIOError);
        }
        loops_.append(new controlLoop(model, motions, e.dict()));

        const word output(loops_.last().entry() + '.' + loops_.last().parameter());
        if (outputs.found(output))
        {
            FatalIOErrorInFunction(e.dict())
                << "loop " << e.keyword() << " of " << dict.name() << " sets "
                << output << ", which another loop sets already"
                << exit(FatalIOError);
        }
        outputs.append(output);
    }

    if (loops_.empty())
    {
        FatalIOErrorInFunction(loopsDict)
            << "loops of " << dict.name() << " is empty: at least one"
            << " controlled parameter is needed" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::flightControllers::PID::start()
{
    for (controlLoop& loop : loops_)
    {
        loop.start();
    }
}


void Foam::flightControllers::PID::control(const scalar t, const scalar dt)
{
    for (controlLoop& loop : loops_)
    {
        set(loop.entry(), loop.parameter(), loop.update(t, dt), t);
    }
}


void Foam::flightControllers::PID::log(Ostream& os) const
{
    for (const controlLoop& loop : loops_)
    {
        os  << ' ' << loop.name() << " (";
        for (const controlTerm& term : loop.terms())
        {
            os  << term.name() << " e " << term.error() << " eDot "
                << term.errorRate() << ", ";
        }
        os  << "u " << loop.u() << ") " << loop.entry() << '.'
            << loop.parameter() << " = " << loop.output() << ';';
    }
}


Foam::wordList Foam::flightControllers::PID::recordNames() const
{
    wordList names;
    for (const controlLoop& loop : loops_)
    {
        names.append(loop.recordNames());
    }
    return names;
}


Foam::scalarList Foam::flightControllers::PID::record() const
{
    scalarList values;
    for (const controlLoop& loop : loops_)
    {
        values.append(loop.record());
    }
    return values;
}


void Foam::flightControllers::PID::writeTypeState(dictionary& dict) const
{
    for (const controlLoop& loop : loops_)
    {
        dictionary loopDict;
        loop.writeState(loopDict);
        dict.add(loop.name(), loopDict);
    }
}


void Foam::flightControllers::PID::readTypeState(const dictionary& dict)
{
    for (controlLoop& loop : loops_)
    {
        loop.readState(dict.subDict(loop.name()));
    }
}


void Foam::flightControllers::PID::write(Ostream& os) const
{
    flightController::write(os);
    os.beginBlock("loops");
    for (const controlLoop& loop : loops_)
    {
        os.beginBlock(loop.name());
        loop.write(os);
        os.endBlock();
    }
    os.endBlock();
}


// ************************************************************************* //
