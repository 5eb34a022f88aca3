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

#include "stepTimers.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(stepTimers, 0);
}

const Foam::word Foam::stepTimers::meshUpdateStart("meshUpdateStart");

const Foam::word Foam::stepTimers::meshUpdated("meshUpdated");

Foam::stepTimers::clockSource Foam::stepTimers::source_(&clock::now);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stepTimers::stepTimers(const objectRegistry& db)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            db.time().timeName(),
            db.time(),
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            true
        )
    ),
    topLevel_(0),
    lapStart_(now()),
    lapTopLevel_(0),
    lastTimeIndex_(-1)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::stepTimers& Foam::stepTimers::New(const objectRegistry& db)
{
    const Time& runTime = db.time();

    stepTimers* ptr = runTime.getObjectPtr<stepTimers>(typeName);

    if (!ptr)
    {
        ptr = new stepTimers(runTime);
        ptr->store();
    }

    return *ptr;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::stepTimers::close(const word& part, const scalar elapsed)
{
    const scalar inside = open_.remove();

    // The enclosing scope (if any) sees the whole elapsed time as nested:
    // the part inside it now, the rest in add() below; without one it
    // counts as added outside any scope (the laps subtract it)
    if (open_.size())
    {
        open_.last() += inside;
    }
    else
    {
        topLevel_ += inside;
    }

    add(part, elapsed - inside);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::stepTimers::add(const word& part, const scalar s)
{
    if (open_.size())
    {
        open_.last() += s;
    }
    else
    {
        topLevel_ += s;
    }

    accumulate(part, s);
}


void Foam::stepTimers::accumulate(const word& part, const scalar s)
{
    auto iter = seconds_.find(part);

    if (iter.found())
    {
        *iter += s;
    }
    else
    {
        seconds_.insert(part, s);
        parts_.append(part);
    }
}


void Foam::stepTimers::useClock(const clockSource source)
{
    source_ = source ? source : &clock::now;
}


void Foam::stepTimers::stamp(const word& name)
{
    lapStart_ = now();
    lapTopLevel_ = topLevel_;
    stamps_.set(name, lapStart_);
}


Foam::stepTimers::clock::time_point Foam::stepTimers::lap(const word& part)
{
    const clock::time_point reading = now();
    const scalar inside = topLevel_ - lapTopLevel_;
    add(part, seconds(lapStart_, reading) - inside);
    lapStart_ = reading;
    lapTopLevel_ = topLevel_;
    return reading;
}


bool Foam::stepTimers::endLap()
{
    if (trailing_.empty())
    {
        return false;
    }

    lap(trailing_);
    trailing_.clear();
    return true;
}


void Foam::stepTimers::count(const word& name, const label n)
{
    counts_.insert(name);
    accumulate(name, n);
}


Foam::stepTimers::clock::time_point Foam::stepTimers::stampTime
(
    const word& name
) const
{
    const auto iter = stamps_.cfind(name);

    if (!iter.found())
    {
        FatalErrorInFunction
            << "No time stamp " << name << " in this step; stamps: "
            << stamps_.sortedToc() << exit(FatalError);
    }

    return *iter;
}


void Foam::stepTimers::reset()
{
    forAllIters(seconds_, iter)
    {
        *iter = 0;
    }

    stamps_.clear();
    trailing_.clear();
}


void Foam::stepTimers::setLast
(
    const label timeIndex,
    const wordList& columns,
    const scalarList& values
)
{
    last_.clear();
    forAll(columns, i)
    {
        last_.set(columns[i], values[i]);
    }
    lastTimeIndex_ = timeIndex;
}


// ************************************************************************* //
