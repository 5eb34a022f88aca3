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

#include "writeAtEnd.H"
#include "functionObjectKeys.H"
#include "Time.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(writeAtEnd, 0);
    addToRunTimeSelectionTable(functionObject, writeAtEnd, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::writeAtEnd::writeAtEnd
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeFunctionObject(name, runTime)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::writeAtEnd::read(const dictionary& dict)
{
    functionObjectKeys::check(dict, wordList());
    return timeFunctionObject::read(dict);
}


bool Foam::functionObjects::writeAtEnd::execute()
{
    return true;
}


bool Foam::functionObjects::writeAtEnd::write()
{
    return true;
}


bool Foam::functionObjects::writeAtEnd::end()
{
    if (!time_.writeTime() && time_.timeIndex() > time_.startTimeIndex())
    {
        Info<< type() << " " << name() << ": writing the last time "
            << time_.timeName() << " (not a write time)" << endl;
        const_cast<Time&>(time_).writeNow();
    }
    return true;
}


// ************************************************************************* //
