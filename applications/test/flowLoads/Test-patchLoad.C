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
    Tests of bodyLoads::patchLoad on the box (boxLoadsCase.H): plate
    carries the sides xMax and yMin, lid zMax, arm and root nothing.
      - uniform kinematic p0, U = 0: F = rhoInf p0 sum(Sf), M = c ^ F;
      - U = G & x (p = 0): the wall shear F = -rhoInf nu (G & Sf), with the
        laminar transport alone and with a laminar turbulence model;
      - p in Pa with a rho field: factor 1, mu = rho nu;
      - bad input: a FatalError or FatalIOError naming it.
    Every reference is analytic; the errors are relative to its size.

\*---------------------------------------------------------------------------*/

#include "boxLoadsCase.H"

using namespace boxLoadsCase;

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

//- Round-off bound of the relative error of a load
const scalar tol = 1e-13;

//- Expect the loads on plate and lid from the stress factor*(p - mu G),
//- exactly zero on root and arm; print the errors
void expectLoads
(
    const Field<spatialVector>& fx,
    const scalar factor,
    const scalar p,
    const scalar mu
)
{
    ASSERT_EQ(fx.size(), 4);
    EXPECT_TRUE(fx[0] == spatialVector::zero) << str(fx[0]);
    EXPECT_TRUE(fx[2] == spatialVector::zero) << str(fx[2]);

    const spatialVector plate(sideLoad({1, 2}, factor, p, mu));
    const spatialVector lid(sideLoad({5}, factor, p, mu));

    EXPECT_LT(relError(fx[1], plate), tol)
        << str(fx[1]) << " vs " << str(plate);
    EXPECT_LT(relError(fx[3], lid), tol)
        << str(fx[3]) << " vs " << str(lid);

    Info<< "    relative error: plate " << relError(fx[1], plate)
        << ", lid " << relError(fx[3], lid) << endl;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(patchLoad, uniformKinematicPressure)
{
    const scalar p0 = 3.7;
    flowCase flow(sqr(dimVelocity), p0);
    flow.addTransport();

    expectLoads(flow.loads(), rhoInf, p0, 0);

    // The reference is not trivial: both force and moment
    const spatialVector plate(sideLoad({1, 2}, rhoInf, p0, 0));
    EXPECT_GT(mag(plate.w()), 1);
    EXPECT_GT(mag(plate.l()), 1);
}


TEST(patchLoad, wallShearLaminarTransport)
{
    flowCase flow(sqr(dimVelocity), 0);
    flow.setLinearU();
    flow.addTransport();

    expectLoads(flow.loads(), rhoInf, 0, nu);
}


TEST(patchLoad, wallShearLaminarTurbulenceModel)
{
    const scalar p0 = -0.8;
    flowCase flow(sqr(dimVelocity), p0);
    flow.setLinearU();
    flow.addTransport();
    flow.addLaminarModel();

    expectLoads(flow.loads(), rhoInf, p0, nu);
}


TEST(patchLoad, pressureInPascalWithRhoField)
{
    // rho 0.9 from the field, not rhoInf 1.2: factor 1, mu = rho nu
    const scalar p0 = 250, rho = 0.9;
    const std::string keys("rho rho;");

    flowCase flow(dimPressure, p0);
    flow.setLinearU();
    flow.addRho(rho);
    flow.addTransport();
    expectLoads(flow.loads(keys), 1, p0, rho*nu);

    // The same through the incompressible laminar model (rho nuEff)
    flow.addLaminarModel();
    expectLoads(flow.loads(keys), 1, p0, rho*nu);
}


TEST(Errors, patchLoadBadInput)
{
    flowCase flow(sqr(dimVelocity), 1);
    const auto loads = [&](const std::string& keys)
    {
        return [&flow, keys]()
        {
            flow.loads(keys);
        };
    };

    // No viscosity registered
    expectError(loads(""), {"transportProperties"});

    flow.addTransport();
    flow.addRho(1);

    // Kinematic p with a density field
    expectError(loads("rho rho;"), {"kinematic", "rhoInf"});

    expectIOError(loads("rhoInf 0;"), {"rhoInf 0:", "a value > 0 is allowed"});

    // Patches that match nothing, on a body and a merged body
    expectIOError
    (
        loads("bodies { arm { patches (nowhere); } }"),
        {"nowhere", "match no patch", "xMin"}
    );
    expectIOError
    (
        loads
        (
            "bodies { tip { type rigidBody; mergeWith plate; mass 1;"
            " centreOfMass (0 0 0); inertia (0.1 0 0 0.1 0 0.1);"
            " transform (1 0 0 0 1 0 0 0 1) (1 0 0); patches (xMin); } }"
        ),
        {"tip", "not a body of the tree"}
    );
}


TEST(Errors, patchLoadBodyNotInTree)
{
    flowCase flow(sqr(dimVelocity), 1);
    flow.addTransport();
    const RBD::rigidBodyModel model(flow.time(), modelDict());

    // The load's dictionary names a body the model does not have
    const dictionary dict(modelDict("bodies { ghost { patches (xMin); } }"));
    expectIOError
    (
        [&](){ bodyLoad::New(flow.mesh(), model, dict, "patchLoad"); },
        {"ghost", "not a body of the tree"}
    );
}


// ************************************************************************* //
