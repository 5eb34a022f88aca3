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
    Extended articulated-body algorithm (Poletti et al., Algorithm 1;
    Featherstone 2008, Table 7.1 with the hybrid-dynamics modification of
    section 9.2).  Notation of the book: X = Xlambda (parent -> link), S
    motion subspace, c velocity-product acceleration, IA/pA articulated
    inertia/bias force, U = IA S, Dinv = (S^T U)^-1, u = tau - S^T pA.

\*---------------------------------------------------------------------------*/

#include "eABAModel.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Sum of the diagonal magnitudes of an articulated inertia: the scale of a
// pivot S^T IA S
inline Foam::scalar inertiaScale(const Foam::spatialTensor& IA)
{
    Foam::scalar s = 0;
    for (Foam::direction d = 0; d < 6; ++d)
    {
        s += Foam::mag(IA(d, d));
    }
    return s;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::eABAModel::forwardPass1
(
    const rigidBodyModelState& state,
    const Field<spatialVector>& fx
) const
{
    const scalarField& q = state.q();
    const scalarField& qDot = state.qDot();

    joint::XSvc J;

    v_[0] = Zero;

    for (label i = 1; i < nBodies(); ++i)
    {
        joints()[i].jcalc(J, q, qDot);

        S_[i] = J.S;
        S1_[i] = J.S1;
        Xlambda_[i] = J.X & XT_[i];

        const label p = lambda_[i];
        X0_[i] = (p == 0) ? Xlambda_[i] : (Xlambda_[i] & X0_[p]);

        v_[i] = (Xlambda_[i] & v_[p]) + J.v;
        c_[i] = J.c + (v_[i] ^ J.v);

        IA_[i] = I(i);
        pA_[i] = v_[i] ^* (I(i) & v_[i]);

        if (fx.size())
        {
            pA_[i] -= *X0_[i] & fx[i];
        }
    }
}


void Foam::RBD::eABAModel::backwardPass
(
    const scalarField& qDdot,
    const scalarField& tau,
    const bool mapped
) const
{
    for (label i = nBodies() - 1; i > 0; --i)
    {
        const joint& jnt = joints()[i];
        const label qi = jnt.qIndex();
        const label p = lambda_[i];
        const label pi = mapped ? prescribedI_[i] : -1;

        // Inertia and bias force the link passes to its parent (in its own
        // frame)
        spatialTensor Ia;
        spatialVector pa;

        if (pi >= 0)
        {
            // Prescribed joint: the whole subtree inertia is transmitted and
            // the bias includes the known joint acceleration S qdd
            Ia = IA_[i];
            pa = pA_[i] + (IA_[i] & (c_[i] + S1_[i]*qDdot[qi]));
        }
        else if (jnt.nDoF() == 1)
        {
            U1_[i] = IA_[i] & S1_[i];
            const scalar D = S1_[i] && U1_[i];
            if (!(D > SMALL*inertiaScale(IA_[i])))
            {
                singularJoint(i, D);
            }
            Dinv_[i].xx() = 1/D;
            u_[i].x() = tau[qi] - (S1_[i] && pA_[i]);

            if (p == 0) continue;

            Ia = IA_[i] - (U1_[i]*(Dinv_[i].xx()*U1_[i]));
            pa = pA_[i] + (Ia & c_[i]) + U1_[i]*(Dinv_[i].xx()*u_[i].x());
        }
        else
        {
            U_[i] = IA_[i] & S_[i];
            const tensor D(S_[i].T() & U_[i]);
            if (!(det(D) > SMALL*pow3(inertiaScale(IA_[i]))))
            {
                singularJoint(i, det(D));
            }
            Dinv_[i] = D.inv();
            u_[i] = tau.block<vector>(qi) - (S_[i].T() & pA_[i]);

            if (p == 0) continue;

            Ia = IA_[i] - (U_[i] & Dinv_[i] & U_[i].T());
            pa = pA_[i] + (Ia & c_[i]) + (U_[i] & Dinv_[i] & u_[i]);
        }

        if (p != 0)
        {
            IA_[p] +=
                spatialTensor(Xlambda_[i].T()) & Ia & spatialTensor(Xlambda_[i]);
            pA_[p] += Xlambda_[i].T() & pa;
        }
    }
}


void Foam::RBD::eABAModel::forwardPass2
(
    scalarField& qDdot,
    const scalarField& tau,
    const bool mapped
) const
{
    a_[0] = spatialVector(Zero, -g_);

    for (label i = 1; i < nBodies(); ++i)
    {
        const joint& jnt = joints()[i];
        const label qi = jnt.qIndex();
        const label pi = mapped ? prescribedI_[i] : -1;

        a_[i] = (Xlambda_[i] & a_[lambda_[i]]) + c_[i];

        if (pi >= 0)
        {
            a_[i] += S1_[i]*qDdot[qi];

            // Joint force transmitted to the subtree, projected on S, less
            // the force already applied to the joint
            tauPrescribed_[pi] =
                (S1_[i] && ((IA_[i] & a_[i]) + pA_[i])) - tau[qi];
        }
        else if (jnt.nDoF() == 1)
        {
            qDdot[qi] = Dinv_[i].xx()*(u_[i].x() - (U1_[i] && a_[i]));
            a_[i] += S1_[i]*qDdot[qi];
        }
        else
        {
            const vector qDdoti(Dinv_[i] & (u_[i] - (U_[i].T() & a_[i])));

            qDdot[qi] = qDdoti.x();
            qDdot[qi + 1] = qDdoti.y();
            qDdot[qi + 2] = qDdoti.z();

            a_[i] += (S_[i] & qDdoti);
        }
    }
}


void Foam::RBD::eABAModel::forwardDynamics
(
    rigidBodyModelState& state,
    const scalarField& tau,
    const Field<spatialVector>& fx
) const
{
    // A tree grown after setPrescribed has no prescribed joint map
    const bool mapped = (prescribedI_.size() == nBodies());
    if (!mapped && prescribedQ_.size())
    {
        FatalErrorInFunction
            << "the tree changed after setPrescribed: call it again"
            << exit(FatalError);
    }

    forwardPass1(state, fx);
    backwardPass(state.qDdot(), tau, mapped);
    forwardPass2(state.qDdot(), tau, mapped);
}


// ************************************************************************* //
