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

#include "flightDataTables.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::label Foam::flightDataTables::precision = 12;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The folder, created if missing
Foam::fileName created(const Foam::fileName& dir)
{
    Foam::mkDir(dir);
    return dir;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::flightDataTables::writeHeaders()
{
    record_.model().writeJointsHeader(joints_);

    OFstream& os = bodies_;
    os  << "# time";
    for (const word& b : record_.bodies())
    {
        os  << ' ' << b << ":cx " << b << ":cy " << b << ":cz"
            << ' ' << b << ":Fx " << b << ":Fy " << b << ":Fz"
            << ' ' << b << ":Mx " << b << ":My " << b << ":Mz";
    }
    os  << nl << "# c: centre of mass; F: fluid force; M: fluid moment about"
        << " the centre of mass; global frame" << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::flightDataTables::flightDataTables
(
    const fileName& dir,
    const RBD::motionRecord& record
)
:
    record_(record),
    joints_(created(dir)/"joints.dat"),
    bodies_(dir/"bodies.dat")
{
    joints_.precision(precision);
    bodies_.precision(precision);
    writeHeaders();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::flightDataTables::append()
{
    record_.model().writeJointsRow(joints_);

    OFstream& os = bodies_;
    os  << record_.model().state().t();
    for (const label bodyID : record_.bodyIDs())
    {
        const vector c(record_.centreOfMass(bodyID));
        const vector& F = record_.load(bodyID).l();
        const vector M(record_.moment(bodyID, c));

        os  << ' ' << c.x() << ' ' << c.y() << ' ' << c.z()
            << ' ' << F.x() << ' ' << F.y() << ' ' << F.z()
            << ' ' << M.x() << ' ' << M.y() << ' ' << M.z();
    }
    os  << endl;
}


// ************************************************************************* //
