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

void Foam::RBD::eABASolver::predict()
{
    const scalar dt = deltaT();

    q() = q0() + dt*qDot0() + 0.5*sqr(dt)*qDdot0();
    qDot() = qDot0() + dt*qDdot0();
    qDdot() = qDdot0();

    correctQuaternionJoints();
}


void Foam::RBD::eABASolver::write(Ostream& os) const
{
    os.writeEntry("type", type());
}


// ************************************************************************* //
