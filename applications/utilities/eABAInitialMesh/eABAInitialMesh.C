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

Application
    eABAInitialMesh

Group
    grpFlapFoamUtilities

Description
    Moves a mesh made in the reference configuration of a multibody model
    (every joint at q = 0, as OpenFOAM's rigid-body motion assumes) to the
    model's state at the start time: the prescribed joints at their exact
    value at startTime (e.g. a wing at the end of its stroke) and the free
    joints at the initial q of the dictionary.  Without it the first time
    step would jump from q = 0 to the start state.

    Writes the reference points to constant/polyMesh/points0 (kept if
    present, so running twice gives the same mesh) and the moved points to
    constant/polyMesh/points.  The motion solver (eABAMeshMotion) moves the
    mesh from points0 from then on.

    Stops before it reads the case at a number beyond the range of a
    double in system/controlDict or constant/dynamicMeshDict, or deltaT or
    writeInterval <= 0 (runInputCheck: the stock readers would end in a
    floating-point exception).

Usage
    \b eABAInitialMesh [-case DIR]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "pointIOField.H"
#include "eABAMeshMotion.H"
#include "runInputCheck.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

// Write points to constant/polyMesh/<name> of mesh
void writePoints(const fvMesh& mesh, const word& name, const pointField& p)
{
    pointIOField points
    (
        IOobject
        (
            name,
            mesh.time().constant(),
            polyMesh::meshSubDir,
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        p
    );
    Info<< "Writing " << points.objectPath() << endl;
    points.write();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Move a mesh made at q = 0 to the multibody state at the start time"
        " (writes constant/polyMesh/points0 and points)"
    );
    argList::noParallel();
    argList::noFunctionObjects();

    #include "setRootCase.H"

    // What the stock readers do not survive, before they read
    runInputCheck::check(args, wordList({"constant/dynamicMeshDict"}));

    #include "createTime.H"

    fvMesh mesh
    (
        IOobject
        (
            fvMesh::defaultRegion,
            runTime.timeName(),
            runTime,
            IOobject::MUST_READ
        )
    );

    autoPtr<motionSolver> solverPtr(motionSolver::New(mesh));

    const eABAMeshMotion* motionPtr = isA<eABAMeshMotion>(solverPtr());
    if (!motionPtr)
    {
        FatalErrorInFunction
            << "constant/dynamicMeshDict selects the motion solver "
            << solverPtr->type() << "; eABAInitialMesh needs "
            << eABAMeshMotion::typeName << exit(FatalError);
    }
    const eABAMeshMotion& motion = *motionPtr;

    const pointField newPoints(motion.curPoints());

    Info<< "Start state at t = " << runTime.value() << ": q = "
        << motion.model().state().q() << nl
        << "Largest point displacement from q = 0: "
        << gMax(mag(newPoints - motion.points0())) << nl << endl;

    // The reference points (q = 0) and the points of the start state
    writePoints(mesh, "points0", motion.points0());
    writePoints(mesh, "points", newPoints);

    Info<< nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
