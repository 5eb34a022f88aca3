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
#include "dictionaryRead.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(eABAModel, 0);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Eigenvalues of a symmetric tensor, ascending (the closed form of Smith
// 1961; OpenFOAM's eigenValues warns of complex values for a multiple one)
Foam::vector principalMoments(const Foam::symmTensor& A)
{
    using namespace Foam;

    const scalar p1 = sqr(A.xy()) + sqr(A.xz()) + sqr(A.yz());
    if (p1 == 0)
    {
        const vector d(A.xx(), A.yy(), A.zz());
        const scalar lo = cmptMin(d);
        const scalar hi = cmptMax(d);
        return vector(lo, cmptSum(d) - lo - hi, hi);
    }

    const scalar q = tr(A)/3;
    const scalar p2 =
        sqr(A.xx() - q) + sqr(A.yy() - q) + sqr(A.zz() - q) + 2*p1;
    const scalar p = Foam::sqrt(p2/6);
    const scalar r = det((A - q*symmTensor::I)/p)/2;
    const scalar phi = Foam::acos(max(scalar(-1), min(scalar(1), r)))/3;

    const scalar hi = q + 2*p*Foam::cos(phi);
    const scalar lo = q + 2*p*Foam::cos(phi + constant::mathematical::twoPi/3);
    return vector(lo, 3*q - hi - lo, hi);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::eABAModel::checkBodies() const
{
    for (const entry& e : bodiesDict_)
    {
        if (!e.isDict())
        {
            continue;
        }
        const dictionary& dict = e.dict();

        readAllowed
        (
            dict, "mass", 0.0, allowed::atLeast(0.0).noting("0: no mass")
        );

        if (!dict.found("inertia"))
        {
            continue;
        }

        // Principal moments, ascending
        const symmTensor J(dict.get<symmTensor>("inertia"));
        const vector ev(principalMoments(J));
        const scalar tol = 1e-12*cmptMax(cmptMag(ev));

        if (cmptMin(ev) < -tol || ev.x() + ev.y() < ev.z() - tol)
        {
            FatalIOErrorInFunction(dict)
                << "body " << e.keyword() << ": inertia " << J
                << " has principal moments " << ev << ": the inertia about"
                << " the centre of mass must be symmetric positive"
                << " semi-definite (principal moments >= 0) with each"
                << " principal moment at most the sum of the other two"
                << " (triangle inequality)" << exit(FatalIOError);
        }
    }
}


void Foam::RBD::eABAModel::singularJoint(const label i, const scalar D) const
{
    const joint& jnt = joints()[i];
    const dictionary* dictPtr = bodiesDict_.findDict(name(i));

    FatalIOErrorInFunction(dictPtr ? *dictPtr : bodiesDict_)
        << "the free joint " << jnt.type() << " (q index " << jnt.qIndex()
        << ") of body " << name(i) << " moves no inertia (S^T IA S = " << D
        << "): its acceleration is undefined, e.g. a leaf body of mass 0 or"
        << " a point mass on the joint's rotation axis.  Allowed: a body (or"
        << " subtree) with mass or inertia along the joint's motion, or the"
        << " joint prescribed (imposedMotion)" << exit(FatalIOError);
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
    prescribedI_(nBodies(), -1),
    bodiesDict_(dict.subDict("bodies"))
{
    checkBodies();
}


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
