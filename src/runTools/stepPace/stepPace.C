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

#include "stepPace.H"
#include "functionObjectKeys.H"
#include "dictionaryRead.H"
#include "Time.H"
#include "addToRunTimeSelectionTable.H"

#include <thread>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(stepPace, 0);
    addToRunTimeSelectionTable(functionObject, stepPace, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::stepPace::stepPace
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeFunctionObject(name, runTime),
    minStepTime_(0),
    last_(std::chrono::steady_clock::now())
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::functionObjects::stepPace::keys()
{
    static const wordList k({"minStepTime"});
    return k;
}


bool Foam::functionObjects::stepPace::read(const dictionary& dict)
{
    functionObjectKeys::check(dict, keys());
    minStepTime_ = readAllowed
    (
        dict, "minStepTime", allowed::openClosed(0.0, 600.0)
    );
    Info<< type() << " " << name() << ": each step held to at least "
        << minStepTime_ << " s of wall-clock" << endl;
    return timeFunctionObject::read(dict);
}


bool Foam::functionObjects::stepPace::execute()
{
    using clock = std::chrono::steady_clock;
    const auto until =
        last_
      + std::chrono::duration_cast<clock::duration>
        (
            std::chrono::duration<double>(minStepTime_)
        );
    std::this_thread::sleep_until(until);
    last_ = clock::now();
    return true;
}


bool Foam::functionObjects::stepPace::write()
{
    return true;
}


// ************************************************************************* //
