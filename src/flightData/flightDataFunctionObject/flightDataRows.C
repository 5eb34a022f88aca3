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

#include "flightDataFunctionObject.H"
#include "stepTimers.H"
#include "flightController.H"
#include "Time.H"

#include <limits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Column names prefix_0, prefix_1, ... for the given indices
wordList indexed(const word& prefix, const labelUList& indices)
{
    wordList names(indices.size());
    forAll(indices, i)
    {
        names[i] = prefix + "_" + Foam::name(indices[i]);
    }
    return names;
}


//- The components of a vector, of a tensor (row-major)
scalarList components(const vector& v)
{
    return scalarList({v.x(), v.y(), v.z()});
}

scalarList components(const tensor& t)
{
    scalarList values(9);
    for (direction i = 0; i < 9; ++i)
    {
        values[i] = t[i];
    }
    return values;
}


//- Append an entry (dataset name, column names, values) to a row
void addEntry
(
    flightDataFile::row& r,
    const word& name,
    const wordList& columns,
    const scalarList& values
)
{
    r.append(flightDataFile::entry{name, columns, values});
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::flightData::addJoints
(
    flightDataFile::row& r,
    const bool withLoads
) const
{
    const RBD::eABAMotion& model = motion_->model();
    const RBD::rigidBodyModelState& s = model.state();
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();

    const labelList dofs(identity(model.nDoF()));
    addEntry(r, "joints/q", indexed("q", dofs), s.q());
    addEntry(r, "joints/qDot", indexed("qDot", dofs), s.qDot());
    addEntry(r, "joints/qDdot", indexed("qDdot", dofs), s.qDdot());

    const labelList& prescribed = model.prescribed();
    if (prescribed.size())
    {
        addEntry
        (
            r, "joints/tau", indexed("tau", prescribed),
            withLoads
          ? scalarList(model.prescribedTau())
          : scalarList(prescribed.size(), nan)
        );
        addEntry
        (
            r, "joints/power", indexed("power", prescribed),
            withLoads
          ? scalarList(model.prescribedPower(s)())
          : scalarList(prescribed.size(), nan)
        );
    }
}


void Foam::functionObjects::flightData::addBodies
(
    flightDataFile::row& r,
    const bool withLoads
) const
{
    const RBD::motionRecord& m = *motion_;
    const RBD::eABAMotion& model = m.model();
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    const wordList xyz({"x", "y", "z"});
    const scalar qRef = 0.5*rhoInf_*sqr(Uref_);

    forAll(bodies_, i)
    {
        const word& body = bodies_[i];
        const label bodyID = bodyIDs_[i];
        const word prefix("bodies/" + body + "/");

        const vector c(m.centreOfMass(bodyID));
        // v takes a point in the body frame: the centre of mass there
        const spatialVector v(model.v(bodyID, model.I(bodyID).c()));
        const tensor R(model.X0(bodyID).E().T());

        addEntry(r, prefix + "position", xyz, components(c));
        addEntry(r, prefix + "velocity", xyz, components(v.l()));
        addEntry(r, prefix + "angularVelocity", xyz, components(v.w()));
        addEntry
        (
            r,
            prefix + "orientation",
            wordList
            ({
                "xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"
            }),
            components(R)
        );

        // The load: force, and moment about the chosen centre of mass
        vector F(vector::uniform(nan));
        vector M(vector::uniform(nan));
        if (withLoads)
        {
            F = m.load(bodyID).l();
            M = m.moment(bodyID, m.centreOfMass(momentAbout_[i]));
        }
        addEntry(r, prefix + "force", xyz, components(F));
        addEntry(r, prefix + "moment", xyz, components(M));

        addEntry
        (
            r,
            "coefficients/" + body,
            wordList({"C_xI", "C_zI", "C_m"}),
            scalarList
            ({
                F.x()/(qRef*area_[i]),
                F.z()/(qRef*area_[i]),
                M.y()/(qRef*area_[i]*chord_[i])
            })
        );
    }
}


void Foam::functionObjects::flightData::addTimers
(
    flightDataFile::row& r,
    const bool withLoads
) const
{
    // The step's timers (maxima over the ranks), if this step's
    const Foam::stepTimers& timers = Foam::stepTimers::New(time_);
    const bool timed =
        withLoads && timers.lastTimeIndex() == time_.timeIndex();
    const wordList timerColumns({"rbd", "overset", "pimple", "total"});
    scalarList t(timerColumns.size(), std::numeric_limits<scalar>::quiet_NaN());
    if (timed)
    {
        forAll(timerColumns, i)
        {
            t[i] = timers.last(timerColumns[i]);
        }
    }
    addEntry(r, "timers", timerColumns, t);
}


void Foam::functionObjects::flightData::addControl
(
    flightDataFile::row& r
) const
{
    const flightController* controller = motion_->model().controller();
    if (controller)
    {
        addEntry(r, "control", controller->recordNames(), controller->record());
    }
}


Foam::flightDataFile::row
Foam::functionObjects::flightData::makeRow(const bool withLoads) const
{
    flightDataFile::row r;
    addEntry
    (
        r, "time", wordList(), scalarList(1, motion_->model().state().t())
    );
    addJoints(r, withLoads);
    addBodies(r, withLoads);
    addTimers(r, withLoads);
    addControl(r);
    return r;
}


// ************************************************************************* //
