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

Description
    flapFoamTest-runTools: the Usage tables of runProgress.H and stepPace.H
    against their keys(), the function objects' own keys (usageKeys.H).

\*---------------------------------------------------------------------------*/

#include "runProgress.H"
#include "stepPace.H"
#include "usageKeys.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(usageKeys, runProgress)
{
    expectUsageKeys
    (
        usageKeys({"runTools/runProgress/runProgress.H"}),
        functionObjects::runProgress::keys()
    );
}


TEST(usageKeys, stepPace)
{
    expectUsageKeys
    (
        usageKeys({"runTools/stepPace/stepPace.H"}),
        functionObjects::stepPace::keys()
    );
}


// ************************************************************************* //
