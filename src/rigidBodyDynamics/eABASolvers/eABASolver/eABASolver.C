/*---------------------------------------------------------------------------*\
  flapFoam: free-flight simulation of flapping-wing drones on OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "eABASolver.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(eABASolver, 0);
    defineRunTimeSelectionTable(eABASolver, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::eABASolver::eABASolver(eABAMotion& model)
:
    model_(model),
    rtau_(model.nDoF(), Zero),
    rfx_(model.nBodies(), Zero)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::RBD::eABASolver::applyRestraints
(
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    rtau_ = tau;

    if (fx.size())
    {
        rfx_ = fx;
    }
    else
    {
        rfx_ = Zero;
    }

    model_.applyRestraints(rtau_, rfx_, state());
}


void Foam::RBD::eABASolver::correctQuaternionJoints()
{
    if (!model_.unitQuaternions())
    {
        return;
    }

    for (const joint& jnt : model_.joints())
    {
        if (!jnt.unitQuaternion())
        {
            continue;
        }

        // Integrated rotation vector of the step: q stores the vector part
        // of the rotation, its change is applied to the previous quaternion
        const label qi = jnt.qIndex();
        const vector dTheta(q().block<vector>(qi) - q0().block<vector>(qi));
        const scalar magDTheta = mag(dTheta);

        if (magDTheta > SMALL)
        {
            const quaternion dq(dTheta/magDTheta, cos(magDTheta), true);
            jnt.unitQuaternion(normalize(jnt.unitQuaternion(q0())*dq), q());
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::eABASolver::write(Ostream& os) const
{
    os.writeEntry("type", type());
}


// ************************************************************************* //
