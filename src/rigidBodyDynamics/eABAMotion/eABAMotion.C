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

#include "eABAMotion.H"
#include "unitConversion.H"
#include "mathematicalConstants.H"
#include "eABASolver.H"
#include "Time.H"
#include "StringStream.H"
#include "flightController.H"
#include "dictionaryRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(eABAMotion, 0);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::eABAMotion::readCoeffs(const dictionary& dict)
{
    nIter_ = readAllowed(dict, "nIter", 1, allowed::atLeast<label>(1));
    aRelax_ =
        readAllowed
        (
            dict, "accelerationRelaxation", 1.0, allowed::openClosed(0.0, 1.0)
        );
    aDamp_ =
        readAllowed
        (
            dict, "accelerationDamping", 1.0, allowed::openClosed(0.0, 1.0)
        );

    report_ = dict.getOrDefault<Switch>("report", false);

    if (dict.found("g"))
    {
        g() = dict.get<vector>("g");
    }
}


void Foam::RBD::eABAMotion::initialise()
{
    setPrescribed(imposedMotions_.joints());

    // Body transforms of the zero state: the reference for point motion
    forwardDynamicsCorrection(rigidBodyModelState(*this));
    X00_ = X0_;

    forwardDynamicsCorrection(motionState_);
}


bool Foam::RBD::eABAMotion::isRestart(const dictionary& stateDict) const
{
    const scalar deltaT = stateDict.getOrDefault<scalar>("deltaT", 0);
    const scalar t = stateDict.getOrDefault<scalar>("t", -GREAT);

    return deltaT > 0 && mag(t - time().value()) <= 0.5*deltaT;
}


void Foam::RBD::eABAMotion::startAfresh(const dictionary& stateDict)
{
    motionState_.t() = time().value();
    motionState_.deltaT() = 0;

    const scalarField tau(nDoF(), Zero);
    const Field<spatialVector> fx(nBodies(), Zero);
    evaluate(motionState_, tau, fx);

    motionState0_ = motionState_;

    reportChanges(stateDict);
}


void Foam::RBD::eABAMotion::reportChanges(const dictionary& stateDict) const
{
    // Free joints keep the file's q and qDot: only qDdot can change
    const wordList names({"q", "qDot", "qDdot"});
    const scalarField* values[] =
        {&motionState_.q(), &motionState_.qDot(), &motionState_.qDdot()};

    // Names of the bodies of the q indices
    labelList qBody(nDoF(), -1);
    for (label i = 1; i < nBodies(); ++i)
    {
        for (label k = 0; k < joints()[i].nDoF(); ++k)
        {
            qBody[joints()[i].qIndex() + k] = i;
        }
    }

    OStringStream changes;
    forAll(names, ni)
    {
        if (!stateDict.found(names[ni]))
        {
            continue;
        }

        const scalarField given(stateDict.get<scalarField>(names[ni]));
        const scalarField& value = *values[ni];

        forAll(value, qi)
        {
            if (mag(value[qi] - given[qi]) > 1e-10*(1 + mag(given[qi])))
            {
                changes
                    << nl << "    " << names[ni] << '[' << qi << "] (body "
                    << name(qBody[qi]) << "): " << given[qi] << " -> "
                    << value[qi];
            }
        }
    }

    if (!changes.str().empty())
    {
        Info<< "Fresh start at t = " << time().timeName() << ": "
            << stateDict.name() << " is not a state written by a step of"
            << " this run (with deltaT > 0 and t = the current time): the"
            << " prescribed joints take their motions' values and the free"
            << " joints' accelerations come from the dynamics (gravity,"
            << " restraints).  Changed from the file:" << changes.str().c_str()
            << nl << endl;
    }
}


void Foam::RBD::eABAMotion::checkAmplitudes() const
{
    // The joint owning each q index
    labelList qJoint(nDoF(), -1);
    for (label i = 1; i < nBodies(); ++i)
    {
        for (label k = 0; k < joints()[i].nDoF(); ++k)
        {
            qJoint[joints()[i].qIndex() + k] = i;
        }
    }

    // An amplitude of a revolute joint is an angle in rad: one past half
    // a turn is a value in degrees (75 for 75 deg flies the drone metres)
    for (const imposedMotion& m : imposedMotions_)
    {
        scalar A = 0;
        if (!m.dict().readIfPresent("amplitude", A))
        {
            continue;
        }
        for (const label qi : m.joints())
        {
            const word& type = joints()[qJoint[qi]].type();
            if (type.size() && type[0] == 'R' && mag(A) > constant::mathematical::pi)
            {
                FatalIOErrorInFunction(m.dict())
                    << "amplitude " << A << " drives the revolute joint "
                    << type << " (q index " << qi << ") in rad: "
                    << radToDeg(A) << " deg, more than half a turn (a value"
                    << " in degrees? " << A << " deg is " << degToRad(A)
                    << " rad); allowed: |amplitude| <= pi"
                    << exit(FatalIOError);
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::eABAMotion::eABAMotion(const Time& time, const dictionary& dict)
:
    eABAMotion(time, dict, dict)
{}


Foam::RBD::eABAMotion::eABAMotion
(
    const Time& time,
    const dictionary& dict,
    const dictionary& stateDict
)
:
    eABAModel(time, dict),
    imposedMotions_(dict, jointDoF()),
    motionState_(*this, stateDict),
    motionState0_(motionState_),
    nIter_(1),
    aRelax_(1),
    aDamp_(1),
    report_(false),
    freshStart_(!isRestart(stateDict)),
    predicted_(false),
    solver_(nullptr),
    controller_(nullptr),
    qDdotPrev_(nDoF(), Zero)
{
    if (dict.found("controller", keyType::LITERAL))
    {
        controller_ = flightController::New
        (
            dict.subDict("controller"), *this, imposedMotions_
        );
    }

    if (!freshStart_)
    {
        // The parameters and blends set by a controller, and its state
        imposedMotions_.readState(stateDict);
        if (controller_.valid())
        {
            controller_->readState(stateDict);
        }
    }

    checkAmplitudes();
    readCoeffs(dict);
    solver_ = eABASolver::New(*this, dict.subDict("solver"));
    initialise();

    if (freshStart_)
    {
        startAfresh(stateDict);
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::RBD::eABAMotion::~eABAMotion()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::RBD::eABAMotion::keys()
{
    // ImposedMotion: the paper authors' spelling, read by imposedMotionList
    static const wordList modelKeys
    ({
        "solver", "nIter", "accelerationRelaxation", "accelerationDamping",
        "report", "g", "bodies", "restraints", "imposedMotion",
        "ImposedMotion", "controller", "q", "qDot"
    });

    return modelKeys;
}


Foam::spatialTransform Foam::RBD::eABAMotion::X00(const label bodyID) const
{
    if (merged(bodyID))
    {
        const subBody& mBody = mergedBody(bodyID);
        return mBody.masterXT() & X00_[mBody.masterID()];
    }

    return X00_[bodyID];
}


void Foam::RBD::eABAMotion::newTime()
{
    motionState0_ = motionState_;
    predicted_ = false;

    if (controller_.valid() && controller_->due(motionState_.t()))
    {
        // The model's kinematics of motionState_ (whatever was evaluated
        // since the step's solve), then the controller's measures: only
        // at an update, not every step
        forwardDynamicsCorrection(motionState_);
        controller_->update(motionState_);
    }
}


void Foam::RBD::eABAMotion::impose(rigidBodyModelState& state) const
{
    imposedMotions_.evaluate(state.t(), state.q(), state.qDot(), state.qDdot());
}


void Foam::RBD::eABAMotion::forwardDynamics
(
    rigidBodyModelState& state,
    const scalarField& tau,
    const Field<spatialVector>& fx
) const
{
    const bool relax = (aRelax_ != 1 || aDamp_ != 1);

    if (relax)
    {
        qDdotPrev_ = state.qDdot();
    }

    eABAModel::forwardDynamics(state, tau, fx);

    if (relax)
    {
        // Free joints only: the prescribed accelerations stay exact
        scalarField& qDdot = state.qDdot();
        const labelList& pq = prescribed();
        label pi = 0;

        forAll(qDdot, qi)
        {
            if (pi < pq.size() && pq[pi] == qi)
            {
                ++pi;
                continue;
            }

            qDdot[qi] =
                aDamp_*(aRelax_*qDdot[qi] + (1 - aRelax_)*qDdotPrev_[qi]);
        }
    }
}


void Foam::RBD::eABAMotion::evaluate
(
    rigidBodyModelState& state,
    const scalarField& tau,
    const Field<spatialVector>& fx
) const
{
    impose(state);
    forwardDynamicsCorrection(state);

    scalarField rtau(tau);
    Field<spatialVector> rfx(nBodies(), Zero);
    if (fx.size())
    {
        rfx = fx;
    }
    applyRestraints(rtau, rfx, state);

    eABAModel::forwardDynamics(state, rtau, rfx);
    forwardDynamicsCorrection(state);
}


void Foam::RBD::eABAMotion::scatterState()
{
    Pstream::scatter(motionState_);
    Pstream::scatter(tauPrescribed_);

    forwardDynamicsCorrection(motionState_);
}


void Foam::RBD::eABAMotion::predict(const scalar t, const scalar deltaT)
{
    motionState_.t() = t;
    motionState_.deltaT() = deltaT;

    if (Pstream::master())
    {
        solver_->predict();
        impose(motionState_);
    }

    scatterState();
    predicted_ = true;
}


void Foam::RBD::eABAMotion::solve
(
    const scalar t,
    const scalar deltaT,
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    if (!predicted_)
    {
        predict(t, deltaT);
    }

    motionState_.t() = t;
    motionState_.deltaT() = deltaT;

    if (Pstream::master())
    {
        solver_->solve(tau, fx);
        impose(motionState_);
    }

    scatterState();
}


bool Foam::RBD::eABAMotion::read(const dictionary& dict)
{
    const bool ok = rigidBodyModel::read(dict);
    readCoeffs(dict);
    return ok;
}


// ************************************************************************* //
