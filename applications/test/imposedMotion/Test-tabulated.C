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
    flapFoamTest-imposedMotion: imposedMotions::tabulated (periodic cubic
    spline): the cyclic tridiagonal solver against its residual,
    derivatives, knots reproduced, periodicity, C2 continuity at the knots
    and the wrap, convergence of the spline of a sine, file input equal to
    values input; bad tables and files are FatalIOErrors naming the key.

\*---------------------------------------------------------------------------*/

#include "imposedMotionTests.H"

// * * * * * * * * * * * * * * * * tabulated * * * * * * * * * * * * * * * * //

TEST(Tabulated, CyclicTridiagonalSolverResidual)
{
    std::mt19937 gen(12345);
    std::uniform_real_distribution<scalar> unif(0.1, 1.0);

    for (const label m : {3, 4, 5, 10, 37})
    {
        scalarList a(m), b(m), c(m), d(m), x;
        for (label i = 0; i < m; ++i)
        {
            a[i] = unif(gen);
            c[i] = (i % 2 ? -1 : 1)*unif(gen);
            b[i] = mag(a[i]) + mag(c[i]) + unif(gen);
            d[i] = 2*unif(gen) - 1;
        }

        imposedMotions::tabulated::solveCyclicTridiagonal(a, b, c, d, x);
        ASSERT_EQ(x.size(), m);

        // Residual of A x = d, indices periodic
        for (label i = 0; i < m; ++i)
        {
            const scalar Ax =
                a[i]*x[(i + m - 1) % m] + b[i]*x[i] + c[i]*x[(i + 1) % m];
            EXPECT_NEAR(Ax, d[i], 1e-13) << "m = " << m << ", row " << i;
        }
    }
}


TEST(Tabulated, DerivativesMatchFiniteDifferences)
{
    auto m = makeMotion
    (
        "type tabulated; joint 0; offset 0.2; " + valuesEntry(tabT, tabQ)
    );
    checkDerivatives(*m, 0, 0.05);
}


TEST(Tabulated, ReproducesKnotsAndIsPeriodic)
{
    const scalar P = 0.05, offset = 0.2;
    auto m = makeMotion
    (
        "type tabulated; joint 0; offset 0.2; " + valuesEntry(tabT, tabQ)
    );

    const auto& tab = refCast<const imposedMotions::tabulated>(*m);
    EXPECT_DOUBLE_EQ(tab.period(), P);

    // Knots: exact
    for (size_t k = 0; k < tabT.size(); ++k)
    {
        EXPECT_DOUBLE_EQ(eval(*m, 0, tabT[k]).q, tabQ[k] + offset)
            << "knot " << k;
    }

    // Periodic: q(t + n P) = q(t), also before t_0
    for (label k = 0; k < 40; ++k)
    {
        const scalar t = 0.3 + 0.00123*k;
        const jointState s = eval(*m, 0, t);
        for (const label n : {-7, -1, 1, 3})
        {
            const jointState sn = eval(*m, 0, t + n*P);
            EXPECT_NEAR(sn.q, s.q, 1e-12);
            EXPECT_NEAR(sn.qDot, s.qDot, 1e-9);
            EXPECT_NEAR(sn.qDdot, s.qDdot, 1e-6);
        }
    }
}


TEST(Tabulated, ContinuousSecondDerivativeAtKnotsAndWrap)
{
    auto m = makeMotion("type tabulated; joint 0; " + valuesEntry(tabT, tabQ));

    scalar scale1 = 0, scale2 = 0;
    for (label k = 0; k < 200; ++k)
    {
        const jointState s = eval(*m, 0, 0.3 + 0.05*k/200);
        scale1 = max(scale1, mag(s.qDot));
        scale2 = max(scale2, mag(s.qDdot));
    }

    // Left and right limits at every knot; the last is the wrap t_n ~ t_0
    const scalar eps = 1e-10;
    for (size_t k = 1; k < tabT.size(); ++k)
    {
        const scalar tk = tabT[k];
        const jointState l = eval(*m, 0, tk - eps);
        const jointState r = eval(*m, 0, tk + eps);
        EXPECT_NEAR(l.q, r.q, 1e-7) << "knot " << k;
        EXPECT_NEAR(l.qDot, r.qDot, 1e-6*scale1) << "knot " << k;
        EXPECT_NEAR(l.qDdot, r.qDdot, 1e-6*scale2) << "knot " << k;
    }
}


TEST(Tabulated, SplineOfSineConverges)
{
    // q = A sin(2 pi t/P) sampled at 64 intervals over one period
    const scalar A = 1.3, P = 0.05, w = twoPi/P;
    const label n = 64;

    std::vector<scalar> t(n + 1), q(n + 1);
    for (label k = 0; k <= n; ++k)
    {
        t[k] = P*k/n;
        q[k] = A*std::sin(w*t[k]);   // q[n] ~ -3e-16: periodic within 1e-12
    }

    auto m = makeMotion("type tabulated; joint 0; " + valuesEntry(t, q));
    checkDerivatives(*m, 0, P);

    scalar errQ = 0, errQDot = 0;
    for (label k = 0; k < 1000; ++k)
    {
        const scalar tk = -0.3*P + 2.1*P*k/1000;
        const jointState s = eval(*m, 0, tk);
        errQ = max(errQ, mag(s.q - A*std::sin(w*tk)));
        errQDot = max(errQDot, mag(s.qDot - A*w*std::cos(w*tk)));
    }

    EXPECT_LE(errQ, 1e-5*A);
    EXPECT_LE(errQDot, 1e-3*A*w);
}


TEST(Tabulated, FileMatchesValues)
{
    tempDir tmp;
    ASSERT_FALSE(tmp.dir().empty()) << "cannot make a temporary directory";

    // Two columns, comments and blank lines
    {
        OFstream os(tmp.dir()/"kinematics.dat");
        os.precision(17);
        os  << "# measured flapping angle" << nl
            << "# t [s]   q [rad]" << nl << nl;
        for (size_t k = 0; k < tabT.size(); ++k)
        {
            os  << tabT[k] << "   " << tabQ[k];
            if (k == 2)
            {
                os  << "   # a comment after the numbers";
            }
            os  << nl;
        }
        os  << nl;
    }

    // The file name is expanded: environment variables
    ::setenv("FLAPFOAM_TEST_DIR", tmp.dir().c_str(), 1);

    auto fromFile = makeMotion
    (
        "type tabulated; joint 0; offset 0.2;"
        " file \"$FLAPFOAM_TEST_DIR/kinematics.dat\";"
    );
    auto fromValues = makeMotion
    (
        "type tabulated; joint 0; offset 0.2; " + valuesEntry(tabT, tabQ)
    );

    checkDerivatives(*fromFile, 0, 0.05);

    for (label k = 0; k < 60; ++k)
    {
        const scalar t = 0.0019*k - 0.02;
        const jointState a = eval(*fromFile, 0, t);
        const jointState b = eval(*fromValues, 0, t);
        EXPECT_DOUBLE_EQ(a.q, b.q);
        EXPECT_DOUBLE_EQ(a.qDot, b.qDot);
        EXPECT_DOUBLE_EQ(a.qDdot, b.qDdot);
    }

    // write() keeps the file name as given
    EXPECT_NE
    (
        writtenText(*fromFile).find("$FLAPFOAM_TEST_DIR/kinematics.dat"),
        std::string::npos
    ) << writtenText(*fromFile);
}


TEST(Errors, TabulatedBadInput)
{
    // Times not strictly increasing: equal, decreasing
    expectMotionError
    (
        "type tabulated; joint 0;"
        " values ((0 0) (0.1 1) (0.1 2) (0.3 -1) (0.4 0));",
        {"'values'", "strictly increasing"}
    );
    expectMotionError
    (
        "type tabulated; joint 0;"
        " values ((0 0) (0.2 1) (0.1 2) (0.3 -1) (0.4 0));",
        {"'values'", "strictly increasing"}
    );

    // Not periodic
    expectMotionError
    (
        "type tabulated; joint 0;"
        " values ((0 0) (0.1 1) (0.2 2) (0.3 -1) (0.4 1e-9));",
        {"'values'", "periodic"}
    );

    // Too few points
    expectMotionError
    (
        "type tabulated; joint 0; values ((0 0) (0.1 1) (0.2 0));",
        {"'values'", "at least 4"}
    );

    // Both values and file; neither
    expectMotionError
    (
        "type tabulated; joint 0; file \"kin.dat\";"
        " values ((0 0) (0.1 1) (0.2 -1) (0.3 0));",
        {"'values'", "'file'", "exactly one"}
    );
    expectMotionError
    (
        "type tabulated; joint 0; offset 1;",
        {"'values'", "'file'", "exactly one"}
    );

    // Missing file
    expectMotionError
    (
        "type tabulated; joint 0; file \"/nonexistent/flapFoam/kin.dat\";",
        {"'file'", "cannot open"}
    );

    // File errors name the key 'file': bad line, non-increasing times
    tempDir tmp;
    ASSERT_FALSE(tmp.dir().empty());
    {
        OFstream os(tmp.dir()/"bad.dat");
        os  << "0 0" << nl << "0.1 1 7" << nl << "0.2 -1" << nl << "0.3 0"
            << nl;
    }
    {
        OFstream os(tmp.dir()/"decreasing.dat");
        os  << "0 0" << nl << "0.2 1" << nl << "0.1 -1" << nl << "0.3 0"
            << nl;
    }
    expectMotionError
    (
        "type tabulated; joint 0; file \"" + tmp.dir() + "/bad.dat\";",
        {"'file'", "line 2", "two numbers"}
    );
    expectMotionError
    (
        "type tabulated; joint 0; file \"" + tmp.dir()
      + "/decreasing.dat\";",
        {"'file'", "strictly increasing"}
    );
}


// ************************************************************************* //
