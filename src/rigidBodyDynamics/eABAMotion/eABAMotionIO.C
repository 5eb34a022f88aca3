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
#include "eABASolver.H"
#include "Time.H"
#include "IOdictionary.H"
#include "flightController.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::IOobject Foam::RBD::eABAMotion::stateIO
(
    const objectRegistry& db,
    const IOobject::readOption r
)
{
    return IOobject
    (
        "rigidBodyMotionState",
        db.time().timeName(),
        "uniform",
        db,
        r,
        IOobject::NO_WRITE,
        false
    );
}


Foam::dictionary Foam::RBD::eABAMotion::initialState
(
    const objectRegistry& db,
    const dictionary& dict
)
{
    IOobject io(stateIO(db));

    if (io.typeHeaderOk<IOdictionary>(true))
    {
        return IOdictionary(io);
    }

    return dict;
}


bool Foam::RBD::eABAMotion::writeState(const objectRegistry& db) const
{
    // Full precision from the start: the entries are formatted as they are
    // added to the dictionary
    const label oldPrecision = IOstream::precision_;
    IOstream::precision_ = 17;

    IOdictionary dict(stateIO(db, IOobject::NO_READ));
    motionState_.write(dict);
    imposedMotions_.writeState(dict);
    if (controller_.valid())
    {
        controller_->writeState(dict);
    }

    const bool ok = dict.regIOobject::writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        IOstream::UNCOMPRESSED,
        true
    );
    IOstream::precision_ = oldPrecision;

    return ok;
}


void Foam::RBD::eABAMotion::writeJointMap(Ostream& os) const
{
    os  << "Joint state map (q index: body, joint type, prescribed by)" << nl;

    for (label i = 1; i < nBodies(); ++i)
    {
        const joint& jnt = joints()[i];

        for (label k = 0; k < jnt.nDoF(); ++k)
        {
            const label qi = jnt.qIndex() + k;

            os  << "    q[" << qi << "]: body " << name(i)
                << ", joint " << jnt.type();
            if (jnt.nDoF() > 1)
            {
                os  << " component " << k;
            }

            for (const imposedMotion& m : imposedMotions_)
            {
                if (m.joints().found(qi))
                {
                    os  << ", prescribed by " << m.name()
                        << " (" << m.type() << ")";
                }
            }
            os  << nl;
        }
    }
    os  << flush;
}


void Foam::RBD::eABAMotion::status(const label bodyID) const
{
    const spatialTransform X(X0(bodyID));
    const spatialVector vb(v(bodyID, Zero));

    Info<< "Multibody motion of body " << name(bodyID) << nl
        << "    Centre of rotation: " << X.r() << nl
        << "    Orientation: " << X.E() << nl
        << "    Linear velocity: " << vb.l() << nl
        << "    Angular velocity: " << vb.w() << endl;
}


void Foam::RBD::eABAMotion::writeJointsHeader(Ostream& os) const
{
    os  << "# time";
    for (label qi = 0; qi < nDoF(); ++qi)
    {
        os  << " q_" << qi << " qDot_" << qi << " qDdot_" << qi;
    }
    for (const label qi : prescribed())
    {
        os  << " tau_" << qi << " power_" << qi;
    }
    os  << endl;
}


void Foam::RBD::eABAMotion::writeJointsRow(Ostream& os) const
{
    const rigidBodyModelState& s = motionState_;

    os  << s.t();
    forAll(s.q(), qi)
    {
        os  << ' ' << s.q()[qi] << ' ' << s.qDot()[qi] << ' ' << s.qDdot()[qi];
    }

    const scalarField power(prescribedPower(s));
    forAll(power, pi)
    {
        os  << ' ' << prescribedTau()[pi] << ' ' << power[pi];
    }
    os  << endl;
}


void Foam::RBD::eABAMotion::write(Ostream& os) const
{
    eABAModel::write(os);

    os.beginBlock("solver");
    solver_->write(os);
    os.endBlock();

    os.writeEntry("nIter", nIter_);
    os.writeEntry("accelerationRelaxation", aRelax_);
    os.writeEntry("accelerationDamping", aDamp_);
    os.writeEntry("report", report_);
    os.writeEntry("g", g());

    imposedMotions_.write(os);

    if (controller_.valid())
    {
        os.beginBlock("controller");
        controller_->write(os);
        os.endBlock();
    }
}


// ************************************************************************* //
