/*---------------------------------------------------------------------------*\
  flapFoam: free-flight simulation of flapping-wing drones on OpenFOAM v1912
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
    eABASolver(model)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::eABASolvers::symplectic::solve
(
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    // Half-step velocity and full-step position
    qDot() = qDot0() + 0.5*deltaT0()*qDdot();
    q() = q0() + deltaT()*qDot();

    correctQuaternionJoints();

    // Exact prescribed state, then the body state for the restraints
    model_.impose(state());
    model_.forwardDynamicsCorrection(state());

    applyRestraints(tau, fx);
    model_.forwardDynamics(state(), rtau_, rfx_);

    // Second half-step of the velocity
    qDot() += 0.5*deltaT()*qDdot();
}


void Foam::RBD::eABASolvers::symplectic::write(Ostream& os) const
{
    eABASolver::write(os);
}


// ************************************************************************* //
