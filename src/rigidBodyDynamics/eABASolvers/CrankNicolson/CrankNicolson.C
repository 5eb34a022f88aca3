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

#include "CrankNicolson.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace eABASolvers
{
    defineTypeNameAndDebug(CrankNicolson, 0);
    addToRunTimeSelectionTable(eABASolver, CrankNicolson, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::eABASolvers::CrankNicolson::CrankNicolson
(
    eABAMotion& model,
    const dictionary& dict
)
:
    eABASolver(model),
    aoc_(dict.getOrDefault<scalar>("aoc", 0.5)),
    voc_(dict.getOrDefault<scalar>("voc", 0.5))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::eABASolvers::CrankNicolson::solve
(
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    // Accelerations at the current iterate with the exact prescribed state
    model_.impose(state());
    applyRestraints(tau, fx);
    model_.forwardDynamics(state(), rtau_, rfx_);

    const scalar dt = deltaT();

    qDot() = qDot0() + dt*(aoc_*qDdot() + (1 - aoc_)*qDdot0());

    q() = q0() + dt*(voc_*qDot() + (1 - voc_)*qDot0());

    correctQuaternionJoints();
}


void Foam::RBD::eABASolvers::CrankNicolson::write(Ostream& os) const
{
    eABASolver::write(os);
    os.writeEntry("aoc", aoc_);
    os.writeEntry("voc", voc_);
}


// ************************************************************************* //
