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
    Tests of wingAerodynamicsModels::quasiSteady through bodyLoads::
    aerodynamics, on a mesh-free model: a wing on a stroke joint (Rz) and a
    pitch joint (Ry about the span), the root off the stroke axis.  Each
    strip's force is written out here from the definition and
    summed apart from the library; zero relative velocity gives zero force;
    a wing moving along its chord feels only CD0; the centre of pressure
    (CoP0, CoP1) moves the moment by d c x F and leaves the force; the
    aerodynamic power of a
    wing in still air is never positive; the load converges in nStrips; bad
    entries are FatalIOErrors naming the key.

\*---------------------------------------------------------------------------*/

#include "boxLoadsCase.H"
#include "Random.H"

using namespace boxLoadsCase;

namespace
{

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

//- Wing root 0.02 m along y from the stroke axis z; pitch about y (span)
const std::string wingModel
(
    "bodies"
    "{"
    "    arm"
    "    {"
    "        type masslessBody; parent root;"
    "        transform (1 0 0 0 1 0 0 0 1) (0 0 0);"
    "        joint { type Rz; }"
    "    }"
    "    wing"
    "    {"
    "        type rigidBody; parent arm; mass 1e-3; centreOfMass (0 0.03 0);"
    "        inertia (1e-6 0 0 1e-6 0 1e-6);"
    "        transform (1 0 0 0 1 0 0 0 1) (0 0.02 0);"
    "        joint { type Ry; }"
    "    }"
    "}"
    "bodyLoad aerodynamics;"
);

//- The semi-elliptic chord of the tests
const std::string semiElliptic
(
    "chordDistribution semiElliptic; meanChord 0.015;"
);

//- A wing entry with extra (later) keys and a chord distribution
std::string wingEntry
(
    const std::string& extra = "",
    const std::string& chords = semiElliptic
)
{
    return
        "aerodynamics { wing { type quasiSteady; body wing; root (0 0 0);"
        " span (0 1 0); chord (1 0 0); length 0.05; rho 1.2; nStrips 40; "
      + chords + " " + extra + " } }";
}

//- The joint values of the two joints
scalarField two(const scalar a, const scalar b)
{
    scalarField v(2);
    v[0] = a;
    v[1] = b;
    return v;
}


//- The load on the wing for q (stroke, pitch), qDot
spatialVector wingLoad
(
    const std::string& entry,
    const scalarField& q,
    const scalarField& qDot
)
{
    scratchTime time("flapFoamTest-bodyLoads", 1, 1);
    IStringStream is(wingModel + entry);
    const dictionary wingDict(is);
    const RBD::rigidBodyModel model(time(), wingDict);
    RBD::rigidBodyModelState state(model);
    state.q() = q;
    state.qDot() = qDot;
    const autoPtr<bodyLoad> load
    (
        bodyLoad::New(time(), model, wingDict, "vacuum")
    );
    Field<spatialVector> fx(model.nBodies(), spatialVector::one);
    load->loads(state, fx);
    EXPECT_TRUE(fx[model.bodyID("arm")] == spatialVector::zero);
    return fx[model.bodyID("wing")];
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(quasiSteady, atRestNoForce)
{
    const spatialVector f(wingLoad(wingEntry(), two(0.3, 0.2), two(0, 0)));
    EXPECT_TRUE(f == spatialVector::zero) << str(f);

    // Moving with the wind: still no force (pure stroke at q = 0: the
    // wing's points move along -x at omega r, so a uniform wind cannot
    // match them all; a pure pitch rate moves points on the span axis
    // not at all)
    const spatialVector g(wingLoad(wingEntry(), two(0, 0), two(0, 5)));
    EXPECT_TRUE(g == spatialVector::zero) << str(g);
}


TEST(quasiSteady, alongChordOnlyCD0)
{
    // Stroke rate w at q = 0: strip k at radius y_k = 0.02 + r_k moves at
    // -w y_k x, along the chord (x): alpha 0, C_L 0, C_D = CD0; the force
    // is along -(velocity), +x for w > 0
    const scalar w = 7.0;
    const scalar rho = 1.2, CD0 = 0.4, R = 0.05, cbar = 0.015;
    const label N = 40;
    vector F(Zero);
    vector M(Zero);
    for (label k = 0; k < N; ++k)
    {
        const scalar r = (k + 0.5)*R/N;
        const scalar c =
            4*cbar/constant::mathematical::pi*std::sqrt(1 - sqr(r/R));
        const scalar y = 0.02 + r;
        const vector dF(0.5*rho*sqr(w*y)*c*(R/N)*CD0, 0, 0);
        F += dF;
        M += vector(0, y, 0) ^ dF;
    }
    const spatialVector f(wingLoad(wingEntry(), two(0, 0), two(w, 0)));
    const spatialVector ref(M, F);
    EXPECT_LT(relError(f, ref), 1e-13) << str(f) << " vs " << str(ref);
}


TEST(quasiSteady, normalAndInclinedPlate)
{
    // Pitch p about the span: the chord (1 0 0) turns to (cos p, 0, -sin p)
    // and the flow (+x relative to the wing, stroke rate w) meets it at
    // alpha = p.  Per strip, drag along +x and lift along +-z with the sign
    // of (e_L.n)(u.n) >= 0, n = c x s
    const scalar w = 3.0, rho = 1.2, R = 0.05;
    const scalar CL = 1.3, CD0 = 0.35, CD1 = 1.1;
    for (const scalar p : {0.25, 0.7, 1.2, constant::mathematical::piByTwo})
    {
        SCOPED_TRACE(p);
        const vector c(std::cos(p), 0, -std::sin(p));
        const vector s(0, 1, 0);
        const vector n(c ^ s);
        const vector u(1, 0, 0);
        vector eL(s ^ u);
        if ((eL & n)*(u & n) < 0)
        {
            eL = -eL;
        }
        const scalar cl = CL*std::sin(2*p);
        const scalar cd = CD0 + CD1*(1 - std::cos(2*p));
        vector F(Zero);
        const label N = 8;
        for (label k = 0; k < N; ++k)
        {
            const scalar y = 0.02 + (k + 0.5)*R/N;
            F += 0.5*rho*sqr(w*y)*0.01*(R/N)*(cl*eL + cd*u);
        }
        const spatialVector f
        (
            wingLoad
            (
                wingEntry
                (
                    "nStrips 8; CL 1.3; CD0 0.35; CD1 1.1;",
                    "chordDistribution table; chords ((0 0.01) (0.05 0.01));"
                ),
                two(0, p),
                two(w, 0)
            )
        );
        EXPECT_LT(mag(f.l() - F), 1e-13*mag(F)) << str(f) << " vs " << F.x() << " " << F.y() << " " << F.z();
        // Lift pushes the plate the way the air flows through it
        EXPECT_GE((f.l() & n)*(u & n), 0);
    }
}


TEST(quasiSteady, centreOfPressureMovesTheMomentOnly)
{
    // The inclined plate above (constant chord 0.01, alpha = p at every
    // strip): with CoP0 a, CoP1 b each strip's force acts d = (a + b
    // p/(pi/2)) 0.01 along the chord c from the pitch axis, so the force is
    // the same and the moment grows by d c x F
    const scalar w = 3.0, a = -0.1, b = 0.35;
    const std::string table
    (
        "chordDistribution table; chords ((0 0.01) (0.05 0.01));"
    );
    for (const scalar p : {0.0, 0.4, 1.1, constant::mathematical::piByTwo})
    {
        SCOPED_TRACE(p);
        const spatialVector onAxis
        (
            wingLoad(wingEntry("nStrips 8;", table), two(0, p), two(w, 0))
        );
        const spatialVector moved
        (
            wingLoad
            (
                wingEntry("nStrips 8; CoP0 -0.1; CoP1 0.35;", table),
                two(0, p),
                two(w, 0)
            )
        );
        const vector c(std::cos(p), 0, -std::sin(p));
        const scalar d = (a + b*p/constant::mathematical::piByTwo)*0.01;
        const vector dM(d*(c ^ onAxis.l()));
        EXPECT_LT(mag(moved.l() - onAxis.l()), 1e-15*mag(onAxis.l()));
        EXPECT_LT
        (
            mag(moved.w() - onAxis.w() - dM),
            1e-13*mag(onAxis.w()) + 1e-18
        )   << str(moved) << " vs " << str(onAxis);
        // About the pitch axis (the span y) it is the normal force's arm:
        // none along the chord (p = 0, drag only)
        EXPECT_EQ(mag(dM) > 1e-3*mag(onAxis.w()), p > 0);
    }
}


TEST(quasiSteady, powerNeverPositiveInStillAir)
{
    // F.v_O + M.omega (the body's spatial velocity at the global origin)
    // is the sum of dF_k.v_k: lift is normal to u, drag along it
    Random rnd(1234);
    for (label i = 0; i < 50; ++i)
    {
        scalarField q(2);
        scalarField qDot(2);
        for (label j = 0; j < 2; ++j)
        {
            q[j] = 6*rnd.sample01<scalar>();
            qDot[j] = 20*(rnd.sample01<scalar>() - 0.5);
        }
        scratchTime time("flapFoamTest-bodyLoads", 1, 1);
        IStringStream is(wingModel + wingEntry());
        const dictionary dict(is);
        const RBD::rigidBodyModel model(time(), dict);
        RBD::rigidBodyModelState state(model);
        state.q() = q;
        state.qDot() = qDot;
        const autoPtr<bodyLoad> load
        (
            bodyLoad::New(time(), model, dict, "vacuum")
        );
        Field<spatialVector> fx(model.nBodies(), Zero);
        load->loads(state, fx);

        const label wing = model.bodyID("wing");
        const spatialTransform X0(model.X0(wing));
        const spatialVector v(model.v(wing, X0.E() & (-X0.r())));
        const spatialVector& f = fx[wing];
        const scalar power = (f.l() & v.l()) + (f.w() & v.w());
        EXPECT_LE(power, 1e-14*mag(f)*mag(v)) << "sample " << i;
        EXPECT_GT(mag(f), 0);
    }
}


TEST(quasiSteady, convergesInStrips)
{
    // Midpoint strips of the semi-ellipse: the differences between
    // doublings fall (at least 2x each), and 640 strips are within 1e-3
    // of 1280
    const scalarField q(two(0.4, 0.6));
    const scalarField qDot(two(6, -3));
    scalar previous = GREAT;
    spatialVector fine(Zero);
    spatialVector last(wingLoad(wingEntry("nStrips 10;"), q, qDot));
    for (const label n : {20, 40, 80, 160, 320, 640, 1280})
    {
        const std::string nStrips("nStrips " + std::to_string(n) + ";");
        const spatialVector f(wingLoad(wingEntry(nStrips), q, qDot));
        const scalar d = mag(f.l() - last.l());
        EXPECT_LT(d, 0.5*previous) << n;
        previous = d;
        fine = last;
        last = f;
    }
    EXPECT_LT(mag(last.l() - fine.l()), 1e-3*mag(last.l()));
}


TEST(Errors, quasiSteadyBadEntries)
{
    const scalarField q(two(0, 0));
    const scalarField qDot(two(1, 0));
    const std::vector<std::pair<std::string, std::pair<std::string, std::string>>> bad
    ({
        {"span (0 2 0);", {"span", "unit vector"}},
        {"chord (0 1 0);", {"span", "not normal to each other"}},
        {"length 0;", {"length 0:", "a value > 0 is allowed"}},
        {"nStrips 0;", {"nStrips 0:", "a value >= 1 is allowed"}},
        {"rho -1;", {"rho -1:", "a value > 0 is allowed"}},
        {"meanChord 0;", {"meanChord 0:", "a value > 0 is allowed"}},
        {"body ghost;", {"ghost", "not a body of the tree"}},
        {"phse 1;", {"Unknown key 'phse'", "nStrips"}},
        {
            "chordDistribution elliptic;",
            {"chordDistribution elliptic unknown", "2(semiElliptic table)"}
        },
        {"type quasiStatic;", {"quasiStatic", "quasiSteady"}}
    });
    for (const auto& b : bad)
    {
        SCOPED_TRACE(b.first);
        expectIOError
        (
            [&](){ wingLoad(wingEntry(b.first), q, qDot); },
            {b.second.first, b.second.second}
        );
    }
    expectIOError
    (
        [&]()
        {
            wingLoad
            (
                wingEntry("", "chordDistribution table; chords ((0 1));"),
                q,
                qDot
            );
        },
        {"chords", "covering 0 to length"}
    );
    expectIOError
    (
        [&](){ wingLoad(wingEntry("chords ((0 1) (1 1));"), q, qDot); },
        {"chords", "does not belong to chordDistribution semiElliptic"}
    );
}


// ************************************************************************* //
