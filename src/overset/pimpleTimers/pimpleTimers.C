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

#include "pimpleTimers.H"
#include "dictionaryKeys.H"
#include "fvMesh.H"
#include "fvMatrices.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(pimpleTimers, 0);
    addToRunTimeSelectionTable(option, pimpleTimers, dictionary);
}
}

const Foam::word Foam::fv::pimpleTimers::momentumPart("pimpleMomentum");

const Foam::word Foam::fv::pimpleTimers::pressurePart("pimplePressure");

const Foam::word Foam::fv::pimpleTimers::turbulencePart("pimpleTurbulence");


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::pimpleTimers::pimpleTimers
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    timers_(stepTimers::New(mesh.time())),
    nCorrections_(-1)
{
    read(dict);
    fieldNames_ = wordList({"U"});
    applied_.setSize(fieldNames_.size(), false);

    // Registered in the order of a step, for the file header
    timers_.add(momentumPart, 0);
    timers_.add(pressurePart, 0);
    timers_.add(turbulencePart, 0);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::pimpleTimers::constrain
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    timers_.lap(momentumPart);
    timers_.trailingLap(word::null);
    nCorrections_ = 0;
}


void Foam::fv::pimpleTimers::correct(volVectorField& U)
{
    // The first correction after the assembly ends the momentum solve,
    // unless there is none (no momentum predictor)
    const bool momentum =
        nCorrections_ == 0
     && mesh_.solutionDict().subOrEmptyDict("PIMPLE")
       .getOrDefault<bool>("momentumPredictor", true);

    timers_.lap(momentum ? momentumPart : pressurePart);
    timers_.trailingLap(turbulencePart);
    ++nCorrections_;
}


const Foam::wordList& Foam::fv::pimpleTimers::keys()
{
    static const wordList k({"type", "libs", "active"});
    return k;
}


bool Foam::fv::pimpleTimers::read(const dictionary& dict)
{
    checkDictionaryKeys(dict, keys());
    return option::read(dict);
}


// ************************************************************************* //
