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

Description
    Unit tests of eABAMeshMotion on the test box (boxMesh.H) in two cell
    zones, wing (cells of x index >= 2) and background (the others), in
    vacuum: the zones move with the model's bodies, checked against motions
    known in closed form; bad background entries.

\*---------------------------------------------------------------------------*/

#include "eABAMeshMotion.H"
#include "boxMesh.H"
#include "expectError.H"
#include "scratchTime.H"

#include "IOdictionary.H"
#include "IStringStream.H"
#include "pointIOField.H"
#include "cellZone.H"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace Foam;

namespace
{

const scalar deltaT = 1e-3;

//- The coefficients of a body "wing" on JOINT carrying the wing zone, in
//- vacuum, Newmark; extra: more entries of the coefficients
std::string coeffs(const std::string& joint, const std::string& extra)
{
    return
        "eABAMeshMotionCoeffs { solver { type Newmark; } nIter 3;"
        " g (0 0 -9.81); fluidLoad off;"
        " bodies { wing { type rigidBody; parent root; mass 1;"
        " centreOfMass (0 0 0); inertia (1e-3 0 0 1e-3 0 1e-3);"
        " transform (1 0 0 0 1 0 0 0 1) (0 0 0);"
        " joint { type " + joint + "; } cellZone wing; } } "
        + extra + " }";
}


//- A body on a slider (Pz) with the background following it in the
//- given components ("(0 0 1)")
std::string slider(const std::string& components)
{
    return coeffs
    (
        "Pz",
        "background { cellZone background; body wing; components "
      + components + "; }"
    );
}


//- The free fall from rest at time t: -g t^2/2
scalar fallen(const scalar t)
{
    return -0.5*9.81*sqr(t);
}


//- The box in its zones, written (points0 are read), and the motion
class motionCase
{
    scratchTime time_;
    std::unique_ptr<fvMesh> mesh_;

public:

    std::unique_ptr<eABAMeshMotion> motion;
    labelHashSet backgroundPoints, wingPoints;

    explicit motionCase(const std::string& coeffText)
    :
        time_("flapFoamTest-rigidBodyMeshMotion", 1, deltaT),
        mesh_(boxCase::boxMesh(time_()))
    {
        DynamicList<label> wing, background;
        forAll(mesh_->cells(), celli)
        {
            (celli % boxCase::boxCells.x() >= 2 ? wing : background)
                .append(celli);
        }
        List<cellZone*> zones(2);
        zones[0] = new cellZone("wing", wing, 0, mesh_->cellZones());
        zones[1] =
            new cellZone("background", background, 1, mesh_->cellZones());
        mesh_->addZones(List<pointZone*>(), List<faceZone*>(), zones);

        for (const label celli : background)
        {
            backgroundPoints.insert(mesh_->cellPoints()[celli]);
        }
        for (const label celli : wing)
        {
            wingPoints.insert(mesh_->cellPoints()[celli]);
        }

        pointIOField points
        (
            IOobject
            (
                "points", time_().constant(), polyMesh::meshSubDir,
                *mesh_, IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            mesh_->points()
        );
        const label precision = IOstream::defaultPrecision(17);
        points.write();         // every digit: points0 = these points
        IOstream::defaultPrecision(precision);

        const IOdictionary dict
        (
            IOobject
            (
                "dynamicMeshDict", time_().constant(), *mesh_,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            dictionary(IStringStream(coeffText)())
        );
        motion.reset(new eABAMeshMotion(*mesh_, dict));
    }

    const pointField& points0() const
    {
        return mesh_->points();
    }

    //- Advance n steps: the current points
    pointField advance(const label n)
    {
        for (label i = 0; i < n; ++i)
        {
            ++time_();
            motion->solve();
        }
        return motion->curPoints();
    }

    scalar t()
    {
        return time_().value();
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests  * * * * * * * * * * * * * * * * //

// Free fall on a slider (Pz) from rest: z = -g t^2/2, which Newmark's
// average acceleration integrates exactly; the wing zone moves by it, the
// background (following the wing's centre of mass in z only) too
TEST(eABAMeshMotion, freeFallMovesTheZones)
{
    motionCase c(slider("(0 0 1)"));
    const pointField p(c.advance(20));
    const scalar dz = fallen(c.t());
    EXPECT_NEAR(c.t(), 20*deltaT, 1e-15);

    scalar maxError = 0;
    forAll(p, pointi)
    {
        maxError =
            max(maxError, mag(p[pointi] - c.points0()[pointi] - vector(0, 0, dz)));
    }
    EXPECT_LT(maxError, 1e-12) << "dz " << dz;
}


// The background follows only the components it names: (1 1 0) for a
// fall in z leaves it in place, while the wing's own points fall
TEST(eABAMeshMotion, backgroundFollowsItsComponentsOnly)
{
    motionCase c(slider("(1 1 0)"));
    const pointField p(c.advance(10));
    const scalar dz = fallen(c.t());

    label nWing = 0;
    forAll(p, pointi)
    {
        const vector d(p[pointi] - c.points0()[pointi]);
        if (c.backgroundPoints.found(pointi))
        {
            EXPECT_EQ(mag(d), 0) << "background point " << pointi;
        }
        else
        {
            ++nWing;
            EXPECT_LT(mag(d - vector(0, 0, dz)), 1e-12) << "point " << pointi;
        }
    }
    EXPECT_EQ(nWing, 2*4*3);    // x index 3 and 4: 2 planes of 4 x 3 points
}


// A revolute joint (Ry) at constant rate (mass on the axis, no torque):
// q = omega t, and each point of the wing zone (the shared plane too)
// turned about the y axis by q (right-handed); without a background entry
// the others stay
TEST(eABAMeshMotion, rotationTurnsTheWingRigidly)
{
    const scalar omega = 2;
    motionCase c(coeffs("Ry", "qDot (2);"));
    const pointField p(c.advance(25));
    const scalar q = omega*c.t();
    const scalar cq = std::cos(q), sq = std::sin(q);

    forAll(p, pointi)
    {
        const point& p0 = c.points0()[pointi];
        if (!c.wingPoints.found(pointi))
        {
            EXPECT_EQ(mag(p[pointi] - p0), 0) << "point " << pointi;
        }
        else
        {
            const point turned
            (
                cq*p0.x() + sq*p0.z(), p0.y(), -sq*p0.x() + cq*p0.z()
            );
            EXPECT_LT(mag(p[pointi] - turned), 1e-12)
                << "point " << pointi << " q " << q;
        }
    }
}


// Bad background entries: each a FatalIOError naming it
TEST(eABAMeshMotion, badBackground)
{
    expectIOError
    (
        [&]{ motionCase c(slider("(0 2 1)")); },
        {"components (0 2 1)", "each component must be 0 (fixed) or 1"}
    );
    expectIOError
    (
        [&]{ motionCase c(coeffs("Pz",
            "background { cellZone background; body nobody; }")); },
        {"body nobody is not a body of the tree; allowed: 2(root wing)"}
    );
    expectIOError
    (
        [&]{ motionCase c(coeffs("Pz",
            "background { cellZone wing; body wing; }")); },
        {"cellZone wing is both the background and the component of body"}
    );
    expectIOError
    (
        [&]{ motionCase c(coeffs("Pz",
            "background { cellZone nozone; body wing; }")); },
        {"cellZone nozone not found; the mesh has"}
    );
    expectIOError
    (
        [&]{ motionCase c(coeffs("Pz",
            "background { cellZone background; body wing; component (0 0 1); }")); },
        {"Unknown key 'component'"}
    );
}


// ************************************************************************* //
