/*---------------------------------------------------------------------------*\
  flapFoam: free-flight simulation of flapping-wing drones on OpenFOAM v1912
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
