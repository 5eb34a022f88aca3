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

#include "eABAModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(eABAModel, 0);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::eABAModel::eABAModel(const Time& time)
:
    rigidBodyModel(time),
    prescribedI_(nBodies(), -1)
{}


Foam::RBD::eABAModel::eABAModel(const Time& time, const dictionary& dict)
:
    rigidBodyModel(time, dict),
    prescribedI_(nBodies(), -1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::RBD::eABAModel::jointDoF() const
{
    labelList dof(nDoF(), 0);

    for (label i = 1; i < nBodies(); ++i)
    {
        const joint& jnt = joints()[i];

        for (label k = 0; k < jnt.nDoF(); ++k)
        {
            dof[jnt.qIndex() + k] = jnt.nDoF();
        }
    }

    return dof;
}


void Foam::RBD::eABAModel::setPrescribed(const labelUList& qIndices)
{
    prescribedQ_ = qIndices;
    Foam::sort(prescribedQ_);
    tauPrescribed_.setSize(prescribedQ_.size(), Zero);

    // Joint owning each q index
    labelList qBody(nDoF(), -1);
    for (label i = 1; i < nBodies(); ++i)
    {
        const joint& jnt = joints()[i];
        for (label k = 0; k < jnt.nDoF(); ++k)
        {
            qBody[jnt.qIndex() + k] = i;
        }
    }

    prescribedI_.setSize(nBodies());
    prescribedI_ = -1;

    forAll(prescribedQ_, pi)
    {
        const label qi = prescribedQ_[pi];

        if (qi < 0 || qi >= nDoF())
        {
            FatalErrorInFunction
                << "prescribed q index " << qi << " outside 0.."
                << nDoF() - 1 << exit(FatalError);
        }

        const label i = qBody[qi];

        if (joints()[i].nDoF() != 1)
        {
            FatalErrorInFunction
                << "q index " << qi << " belongs to joint " << i << " ("
                << joints()[i].type() << ") with " << joints()[i].nDoF()
                << " degrees of freedom: only 1-DoF joints can be prescribed"
                << exit(FatalError);
        }

        if (prescribedI_[i] != -1)
        {
            FatalErrorInFunction
                << "q index " << qi << " prescribed twice"
                << exit(FatalError);
        }

        prescribedI_[i] = pi;
    }
}


Foam::tmp<Foam::scalarField> Foam::RBD::eABAModel::prescribedPower
(
    const rigidBodyModelState& state
) const
{
    tmp<scalarField> tpower(new scalarField(prescribedQ_.size()));
    scalarField& power = tpower.ref();

    forAll(prescribedQ_, pi)
    {
        power[pi] = tauPrescribed_[pi]*state.qDot()[prescribedQ_[pi]];
    }

    return tpower;
}


// ************************************************************************* //
