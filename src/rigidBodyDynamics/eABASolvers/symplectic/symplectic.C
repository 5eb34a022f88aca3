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

#include "symplectic.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace eABASolvers
{
    defineTypeNameAndDebug(symplectic, 0);
    addToRunTimeSelectionTable(eABASolver, symplectic, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::eABASolvers::symplectic::symplectic
(
    eABAMotion& model,
    const dictionary& dict
)
:
    eABASolver(model),
    qDotNew_(model.nDoF(), Zero),
    qDotHalf_(model.nDoF(), Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::eABASolvers::symplectic::solve
(
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    const scalar dt = deltaT();

    // The estimate of the new velocity (the predictor's or the last
    // correction's): the velocity the new accelerations are evaluated at
    qDotNew_ = qDot();

    // Half-step velocity and full-step position from the previous state
    qDotHalf_ = qDot0() + 0.5*dt*qDdot0();
    q() = q0() + dt*qDotHalf_;

    correctQuaternionJoints();

    // Exact prescribed state, then the body state for the restraints
    qDot() = qDotNew_;
    model_.impose(state());
    model_.forwardDynamicsCorrection(state());

    applyRestraints(tau, fx);
    model_.forwardDynamics(state(), rtau_, rfx_);

    // Second half-step of the velocity
    qDot() = qDotHalf_ + 0.5*dt*qDdot();
}


void Foam::RBD::eABASolvers::symplectic::write(Ostream& os) const
{
    eABASolver::write(os);
}


// ************************************************************************* //
