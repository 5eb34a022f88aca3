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
    flapFoamTest-imposedMotion

Description
    GoogleTest unit tests of libimposedMotion:
      - every motion type: the exact qDot, qDdot against central finite
        differences of q, qDot over two periods (negative times included),
        and closed-form values (extrema, zero crossings, limits in K);
      - tabulated: knots reproduced, periodicity, C2 continuity, convergence
        of the spline of a sine, file input equal to values input, and the
        cyclic tridiagonal solver against its residual;
      - write() then read back gives the same motion (every type, the list);
      - every bad input stops with a FatalIOError whose message names the
        key (FatalError and FatalIOError are made to throw);
      - imposedMotionList: joints ascending, evaluate writes only the
        prescribed entries, empty without the sub-dictionary.

\*---------------------------------------------------------------------------*/

#include "imposedMotion.H"
#include "imposedMotionList.H"
#include "tabulated.H"
#include "wangParametrization.H"
#include "StringStream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

const scalar pi = constant::mathematical::pi;
const scalar twoPi = constant::mathematical::twoPi;


//- Dictionary from text
dictionary makeDict(const std::string& text)
{
    return dictionary(IStringStream(text)());
}


//- Motion from the text of its dictionary
autoPtr<imposedMotion> makeMotion(const std::string& text)
{
    return imposedMotion::New("test", makeDict(text));
}


//- q, qDot, qDdot of one joint
struct jointState
{
    scalar q;
    scalar qDot;
    scalar qDdot;
};


jointState eval(const imposedMotion& m, const label i, const scalar t)
{
    jointState s{0, 0, 0};
    m.evaluate(i, t, s.q, s.qDot, s.qDdot);
    return s;
}


//- Check qDot and qDdot of joint i of m against central differences of q
//- and qDot (step 1e-6 of the period) at many times over two periods,
//- negative times included.  Errors relative to the largest |qDot|, |qDdot|.
void checkDerivatives
(
    const imposedMotion& m,
    const label i,
    const scalar period,
    const scalar tol = 1e-6
)
{
    const label nSample = 251;
    const scalar h = 1e-6*period;

    scalar err1 = 0, scale1 = 0, tErr1 = 0;
    scalar err2 = 0, scale2 = 0, tErr2 = 0;

    for (label k = 0; k < nSample; ++k)
    {
        // Not commensurate with the period: hits no special point exactly
        const scalar t = period*(-0.7 + 2.0*k/(nSample - 1) + 1e-3*M_SQRT2);

        const jointState s = eval(m, i, t);
        const jointState sp = eval(m, i, t + h);
        const jointState sm = eval(m, i, t - h);

        const scalar fd1 = (sp.q - sm.q)/(2*h);
        const scalar fd2 = (sp.qDot - sm.qDot)/(2*h);

        if (mag(fd1 - s.qDot) > err1)
        {
            err1 = mag(fd1 - s.qDot);
            tErr1 = t;
        }
        if (mag(fd2 - s.qDdot) > err2)
        {
            err2 = mag(fd2 - s.qDdot);
            tErr2 = t;
        }
        scale1 = max(scale1, mag(s.qDot));
        scale2 = max(scale2, mag(s.qDdot));
    }

    EXPECT_GT(scale1, 0) << "qDot is zero everywhere";
    EXPECT_GT(scale2, 0) << "qDdot is zero everywhere";
    EXPECT_LE(err1, tol*scale1)
        << "qDot differs from the difference of q by " << err1
        << " at t = " << tErr1 << " (max |qDot| " << scale1 << ')';
    EXPECT_LE(err2, tol*scale2)
        << "qDdot differs from the difference of qDot by " << err2
        << " at t = " << tErr2 << " (max |qDdot| " << scale2 << ')';
}


//- Run f: expect a FatalIOError whose message contains every word
void expectIOError
(
    const std::function<void()>& f,
    std::initializer_list<std::string> words
)
{
    try
    {
        f();
        ADD_FAILURE() << "no FatalIOError";
    }
    catch (const Foam::IOerror& err)
    {
        const std::string msg(err.message());
        for (const std::string& w : words)
        {
            EXPECT_NE(msg.find(w), std::string::npos)
                << "the message lacks \"" << w << "\":\n" << msg;
        }
    }
    catch (const Foam::error& err)
    {
        ADD_FAILURE()
            << "FatalError instead of FatalIOError:\n" << err.message();
    }
}


//- Expect that constructing the motion from text fails naming the words
void expectMotionError
(
    const std::string& text,
    std::initializer_list<std::string> words
)
{
    SCOPED_TRACE(text);
    expectIOError([&](){ makeMotion(text); }, words);
}


//- Text "values ((t q) ...);" with 17 digits
std::string valuesEntry
(
    const std::vector<scalar>& t,
    const std::vector<scalar>& q
)
{
    std::ostringstream os;
    os  << std::setprecision(17) << "values (";
    for (size_t k = 0; k < t.size(); ++k)
    {
        os  << " (" << t[k] << ' ' << q[k] << ')';
    }
    os  << " );";
    return os.str();
}


//- A periodic, non-uniform table: t from 0.3 to 0.35 (period 0.05)
const std::vector<scalar> tabT{0.3, 0.31, 0.325, 0.33, 0.345, 0.35};
const std::vector<scalar> tabQ{0.1, 0.5, -0.2, 0.0, 0.4, 0.1};


//- Write then read back a motion: the text of its write()
std::string writtenText(const imposedMotion& m)
{
    OStringStream os;
    os.precision(17);
    m.write(os);
    return os.str();
}


//- Temporary directory, removed at the end of the test
class tempDir
{
    fileName dir_;

public:

    tempDir()
    {
        const char* tmp = std::getenv("TMPDIR");
        std::string tmpl =
            std::string(tmp && *tmp ? tmp : "/tmp")
          + "/flapFoamTest-imposedMotion-XXXXXX";
        std::vector<char> buf(tmpl.begin(), tmpl.end());
        buf.push_back('\0');
        if (::mkdtemp(buf.data()))
        {
            dir_ = fileName(buf.data());
        }
    }

    ~tempDir()
    {
        if (!dir_.empty())
        {
            rmDir(dir_);
        }
    }

    const fileName& dir() const
    {
        return dir_;
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * harmonic  * * * * * * * * * * * * * * * * //

TEST(Harmonic, DerivativesMatchFiniteDifferences)
{
    auto m = makeMotion
    (
        "type harmonic; joint 0; amplitude 0.9948; frequency 2;"
        " phase 0.3; offset -0.9948;"
    );
    checkDerivatives(*m, 0, 0.5);
}


TEST(Harmonic, ClosedFormValues)
{
    const scalar A = 0.9948, f = 2, q0 = -0.25, w = twoPi*f;
    auto m = makeMotion
    (
        "type harmonic; joint 4; amplitude 0.9948; frequency 2; offset -0.25;"
    );

    EXPECT_EQ(m->type(), "harmonic");
    ASSERT_EQ(m->joints().size(), 1);
    EXPECT_EQ(m->joints()[0], 4);

    // t = 0: q = offset + A, qDot = 0, qDdot = -A w^2
    const jointState s0 = eval(*m, 0, 0);
    EXPECT_NEAR(s0.q, q0 + A, 1e-15);
    EXPECT_NEAR(s0.qDot, 0, 1e-15);
    EXPECT_NEAR(s0.qDdot, -A*w*w, 1e-12*A*w*w);

    // t = T/4: q = offset, qDot = -A w, qDdot = 0
    const jointState s1 = eval(*m, 0, 0.25/f);
    EXPECT_NEAR(s1.q, q0, 1e-14);
    EXPECT_NEAR(s1.qDot, -A*w, 1e-12*A*w);
    EXPECT_NEAR(s1.qDdot, 0, 1e-12*A*w*w);

    // Phase: q(t) = offset + A cos(w t + phase)
    auto mp = makeMotion
    (
        "type harmonic; joint 0; amplitude 2; frequency 3; phase 0.5;"
    );
    EXPECT_NEAR(eval(*mp, 0, 0.1).q, 2*std::cos(twoPi*3*0.1 + 0.5), 1e-14);
}


// * * * * * * * * * * * * * * * * * wang  * * * * * * * * * * * * * * * * * //

TEST(Wang, FlappingDerivativesMatchFiniteDifferences)
{
    for (const char* K : {"0.01", "0.5", "0.9", "0.99"})
    {
        SCOPED_TRACE(std::string("flapping K = ") + K);
        auto m = makeMotion
        (
            std::string("type wang; joint 1; waveform flapping;"
            " amplitude 1.309; frequency 20; phase 0.2; offset 0.1; K ")
          + K + ";"
        );
        checkDerivatives(*m, 0, 1.0/20);
    }
}


TEST(Wang, PitchingDerivativesMatchFiniteDifferences)
{
    for (const char* K : {"0.01", "1", "5", "20"})
    {
        SCOPED_TRACE(std::string("pitching K = ") + K);
        auto m = makeMotion
        (
            std::string("type wang; joint 1; waveform pitching;"
            " amplitude 0.785; frequency 20; phase -0.4; offset 0.05; K ")
          + K + ";"
        );
        checkDerivatives(*m, 0, 1.0/20);
    }
}


TEST(Wang, ClosedFormValues)
{
    const scalar A = 1.309, f = 20, T = 1/f, w = twoPi*f, K = 0.7;

    // Flapping: q(0) = A (maximum, at rest), q(T/4) = 0 with
    // qDot = -A w K/asin(K), q(T/2) = -A
    auto flap = makeMotion
    (
        "type wang; joint 0; waveform flapping; amplitude 1.309;"
        " frequency 20; K 0.7;"
    );
    const jointState f0 = eval(*flap, 0, 0);
    EXPECT_NEAR(f0.q, A, 1e-14);
    EXPECT_NEAR(f0.qDot, 0, 1e-12);
    const jointState f1 = eval(*flap, 0, T/4);
    EXPECT_NEAR(f1.q, 0, 1e-14);
    EXPECT_NEAR(f1.qDot, -A*w*K/std::asin(K), 1e-12*A*w);
    EXPECT_NEAR(eval(*flap, 0, T/2).q, -A, 1e-14);

    // Pitching: q(0) = 0 with qDot = A w K/tanh(K), q(T/4) = A
    auto pitch = makeMotion
    (
        "type wang; joint 0; waveform pitching; amplitude 1.309;"
        " frequency 20; K 0.7; offset 0.2;"
    );
    const jointState p0 = eval(*pitch, 0, 0);
    EXPECT_NEAR(p0.q, 0.2, 1e-14);
    EXPECT_NEAR(p0.qDot, A*w*K/std::tanh(K), 1e-12*A*w);
    EXPECT_NEAR(p0.qDdot, 0, 1e-12*A*w*w);
    EXPECT_NEAR(eval(*pitch, 0, T/4).q, 0.2 + A, 1e-14);
    EXPECT_NEAR(eval(*pitch, 0, 3*T/4).q, 0.2 - A, 1e-14);
}


TEST(Wang, SmallKApproachesSinusoid)
{
    // asin(K c)/asin(K) = c (1 + O(K^2)), tanh(K s)/tanh(K) = s (1 + O(K^2))
    const scalar A = 1.2, f = 5, w = twoPi*f, phase = 0.3;

    auto flap = makeMotion
    (
        "type wang; joint 0; waveform flapping; amplitude 1.2; frequency 5;"
        " phase 0.3; K 1e-5;"
    );
    auto pitch = makeMotion
    (
        "type wang; joint 0; waveform pitching; amplitude 1.2; frequency 5;"
        " phase 0.3; K 1e-5;"
    );

    for (label k = 0; k < 20; ++k)
    {
        const scalar t = 0.0137*k;
        const scalar th = w*t + phase;

        const jointState sf = eval(*flap, 0, t);
        EXPECT_NEAR(sf.q, A*std::cos(th), 1e-9*A);
        EXPECT_NEAR(sf.qDot, -A*w*std::sin(th), 1e-9*A*w);
        EXPECT_NEAR(sf.qDdot, -A*w*w*std::cos(th), 1e-9*A*w*w);

        const jointState sp = eval(*pitch, 0, t);
        EXPECT_NEAR(sp.q, A*std::sin(th), 1e-9*A);
        EXPECT_NEAR(sp.qDot, A*w*std::cos(th), 1e-9*A*w);
        EXPECT_NEAR(sp.qDdot, -A*w*w*std::sin(th), 1e-9*A*w*w);
    }
}


TEST(Wang, LargeKLimits)
{
    // Flapping K -> 1: triangle wave, q(T/8) -> A/2
    auto flap = makeMotion
    (
        "type wang; joint 0; waveform flapping; amplitude 1; frequency 1;"
        " K 0.9999999999;"
    );
    EXPECT_NEAR(eval(*flap, 0, 0.125).q, 0.5, 1e-4);
    // ... with constant speed 4 A f away from the reversals
    EXPECT_NEAR(eval(*flap, 0, 0.125).qDot, -4, 1e-3);

    // Pitching K large: square wave, q(T/8) -> A
    auto pitch = makeMotion
    (
        "type wang; joint 0; waveform pitching; amplitude 1; frequency 1;"
        " K 50;"
    );
    EXPECT_NEAR(eval(*pitch, 0, 0.125).q, 1, 1e-12);
    EXPECT_NEAR(eval(*pitch, 0, 0.625).q, -1, 1e-12);
}


// * * * * * * * * * * * * * * wangParametrization * * * * * * * * * * * * * //

namespace
{

std::string wangParametrizationText(const std::string& extra)
{
    return
        "type wangParametrization; jointList (3 4); Aphi 1.309; fphi 20;"
        " Kphi 0.3; Aalpha 0.785; falpha 20; Kalpha 2; " + extra;
}

}


TEST(WangParametrization, DerivativesMatchFiniteDifferences)
{
    for
    (
        const char* type
      : {"", "motionType standard;", "motionType midStart;"}
    )
    {
        SCOPED_TRACE(type);
        auto m = makeMotion(wangParametrizationText(type));
        checkDerivatives(*m, 0, 1.0/20);
        checkDerivatives(*m, 1, 1.0/20);
    }

    // The authors' dictionary (K = 0.01 for both)
    auto m = makeMotion
    (
        "type wangParametrization; jointList (3 4); Aphi 1.309; fphi 20;"
        " Kphi 0.01; Aalpha 0.785; falpha 20; Kalpha 0.01;"
        " motionType midStart;"
    );
    checkDerivatives(*m, 0, 1.0/20);
    checkDerivatives(*m, 1, 1.0/20);
}


TEST(WangParametrization, JointsAndStandardMatchesWang)
{
    auto m = makeMotion(wangParametrizationText(""));

    ASSERT_EQ(m->joints().size(), 2);
    EXPECT_EQ(m->joints()[0], 3);
    EXPECT_EQ(m->joints()[1], 4);
    EXPECT_EQ(m->jointsKey(), "jointList");

    auto flap = makeMotion
    (
        "type wang; joint 3; waveform flapping; amplitude 1.309;"
        " frequency 20; K 0.3;"
    );
    auto pitch = makeMotion
    (
        "type wang; joint 4; waveform pitching; amplitude 0.785;"
        " frequency 20; K 2;"
    );

    for (label k = 0; k < 30; ++k)
    {
        const scalar t = 0.00317*k - 0.01;
        const jointState a = eval(*m, 0, t), b = eval(*flap, 0, t);
        const jointState c = eval(*m, 1, t), d = eval(*pitch, 0, t);
        EXPECT_DOUBLE_EQ(a.q, b.q);
        EXPECT_DOUBLE_EQ(a.qDot, b.qDot);
        EXPECT_DOUBLE_EQ(a.qDdot, b.qDdot);
        EXPECT_DOUBLE_EQ(c.q, d.q);
        EXPECT_DOUBLE_EQ(c.qDot, d.qDot);
        EXPECT_DOUBLE_EQ(c.qDdot, d.qDdot);
    }

    // Standard: phi(0) = Aphi, alpha(0) = 0
    EXPECT_NEAR(eval(*m, 0, 0).q, 1.309, 1e-14);
    EXPECT_NEAR(eval(*m, 1, 0).q, 0, 1e-14);
}


TEST(WangParametrization, MidStart)
{
    const scalar T = 1.0/20;
    auto stdm = makeMotion(wangParametrizationText(""));
    auto mid = makeMotion(wangParametrizationText("motionType midStart;"));

    // Mid-stroke start: phi(0) = 0 moving towards +Aphi, alpha(0) = Aalpha
    const jointState phi0 = eval(*mid, 0, 0);
    EXPECT_NEAR(phi0.q, 0, 1e-14);
    EXPECT_GT(phi0.qDot, 0);
    EXPECT_NEAR(eval(*mid, 0, T/4).q, 1.309, 1e-14);
    EXPECT_NEAR(eval(*mid, 1, 0).q, 0.785, 1e-14);
    EXPECT_NEAR(eval(*mid, 1, T/4).q, 0, 1e-14);

    // phi_mid(t) = phi_std(t - T/4), alpha_mid(t) = -alpha_std(t - T/4)
    for (label k = 0; k < 40; ++k)
    {
        const scalar t = 0.00291*k - 0.02;
        const jointState pm = eval(*mid, 0, t), ps = eval(*stdm, 0, t - T/4);
        const jointState am = eval(*mid, 1, t), as = eval(*stdm, 1, t - T/4);

        EXPECT_NEAR(pm.q, ps.q, 1e-12);
        EXPECT_NEAR(pm.qDot, ps.qDot, 1e-9*mag(ps.qDot) + 1e-9);
        EXPECT_NEAR(pm.qDdot, ps.qDdot, 1e-9*mag(ps.qDdot) + 1e-6);
        EXPECT_NEAR(am.q, -as.q, 1e-12);
        EXPECT_NEAR(am.qDot, -as.qDot, 1e-9*mag(as.qDot) + 1e-9);
        EXPECT_NEAR(am.qDdot, -as.qDdot, 1e-9*mag(as.qDdot) + 1e-6);
    }
}


// * * * * * * * * * * * * * * * * * fourier * * * * * * * * * * * * * * * * //

TEST(Fourier, DerivativesMatchFiniteDifferences)
{
    auto m = makeMotion
    (
        "type fourier; joint 2; frequency 20; a0 0.1;"
        " a (1.2 0 0.05 0.01); b (0 0.3 -0.02 0.004);"
    );
    checkDerivatives(*m, 0, 1.0/20);
}


TEST(Fourier, MatchesDirectSum)
{
    const scalar f = 7, w = twoPi*f, a0 = -0.3;
    const std::vector<scalar> a{0.8, -0.1, 0.05, 0, 0.02, -0.01, 0.003};
    const std::vector<scalar> b{0.2, 0.15, 0, -0.04, 0.01, 0.002, -0.001};

    auto m = makeMotion
    (
        "type fourier; joint 0; frequency 7; a0 -0.3;"
        " a (0.8 -0.1 0.05 0 0.02 -0.01 0.003);"
        " b (0.2 0.15 0 -0.04 0.01 0.002 -0.001);"
    );

    for (label k = 0; k < 50; ++k)
    {
        const scalar t = 0.0123*k - 0.2;

        // Direct sum with one cos/sin call per harmonic
        scalar q = a0, qDot = 0, qDdot = 0;
        for (size_t n = 1; n <= a.size(); ++n)
        {
            const scalar nw = n*w;
            const scalar c = std::cos(nw*t), s = std::sin(nw*t);
            q += a[n-1]*c + b[n-1]*s;
            qDot += nw*(-a[n-1]*s + b[n-1]*c);
            qDdot -= nw*nw*(a[n-1]*c + b[n-1]*s);
        }

        const jointState st = eval(*m, 0, t);
        EXPECT_NEAR(st.q, q, 1e-12);
        EXPECT_NEAR(st.qDot, qDot, 1e-12*w);
        EXPECT_NEAR(st.qDdot, qDdot, 1e-11*w*w);
    }

    // t = 0: q = a0 + sum a_n
    scalar q0 = a0;
    for (const scalar an : a)
    {
        q0 += an;
    }
    EXPECT_NEAR(eval(*m, 0, 0).q, q0, 1e-14);
}


TEST(Fourier, OneCoefficientListDefaultsOtherToZeros)
{
    // Only b: q = b_1 sin(w t); only a: q = a0 + a_1 cos(w t) + a_2 cos(2 w t)
    auto mb = makeMotion("type fourier; joint 0; frequency 2; b (0.5);");
    auto ma = makeMotion
    (
        "type fourier; joint 0; frequency 2; a0 1; a (0.5 0.25);"
    );
    const scalar w = twoPi*2;

    for (const scalar t : {0.0, 0.03, 0.11, 0.4})
    {
        EXPECT_NEAR(eval(*mb, 0, t).q, 0.5*std::sin(w*t), 1e-14);
        EXPECT_NEAR
        (
            eval(*ma, 0, t).q,
            1 + 0.5*std::cos(w*t) + 0.25*std::cos(2*w*t),
            1e-14
        );
    }
}


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


// * * * * * * * * * * * * * * * * write/read  * * * * * * * * * * * * * * * //

TEST(WriteRead, EveryTypeRoundTrips)
{
    const std::vector<std::string> texts
    {
        "type harmonic; joint 0; amplitude 0.9948; frequency 2; phase 0.3;"
        " offset -0.9948;",
        "type wang; joint 1; waveform flapping; amplitude 1.309;"
        " frequency 20; K 0.9; phase 0.1; offset 0.05;",
        "type wang; joint 1; waveform pitching; amplitude 0.785;"
        " frequency 20; K 5;",
        wangParametrizationText("motionType midStart;"),
        "type fourier; joint 2; frequency 20; a (1.2 0.1); b (0 0.3);",
        "type fourier; joint 2; frequency 20; b (0.3);",
        "type tabulated; joint 0; offset 0.2; " + valuesEntry(tabT, tabQ)
    };

    for (const std::string& text : texts)
    {
        SCOPED_TRACE(text);
        auto m1 = makeMotion(text);
        const std::string written(writtenText(*m1));
        auto m2 = makeMotion(written);

        EXPECT_EQ(m2->type(), m1->type()) << written;
        EXPECT_EQ(m2->joints(), m1->joints()) << written;

        forAll(m1->joints(), i)
        {
            for (label k = 0; k < 20; ++k)
            {
                const scalar t = 0.00713*k - 0.03;
                const jointState a = eval(*m1, i, t);
                const jointState b = eval(*m2, i, t);
                EXPECT_NEAR(a.q, b.q, 1e-12*(1 + mag(a.q))) << written;
                EXPECT_NEAR(a.qDot, b.qDot, 1e-10*(1 + mag(a.qDot)));
                EXPECT_NEAR(a.qDdot, b.qDdot, 1e-8*(1 + mag(a.qDdot)));
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Bad input * * * * * * * * * * * * * * * * //

TEST(Errors, UnknownTypeListsValidTypes)
{
    expectMotionError
    (
        "type sinus; joint 0; amplitude 1; frequency 1;",
        {
            "Unknown imposedMotion type sinus",
            "fourier", "harmonic", "tabulated", "wang", "wangParametrization"
        }
    );
}


TEST(Errors, MissingKeys)
{
    expectMotionError("joint 0; amplitude 1; frequency 1;", {"'type'"});
    expectMotionError
    (
        "type harmonic; joint 0; frequency 2;", {"'amplitude'"}
    );
    expectMotionError
    (
        "type harmonic; amplitude 1; frequency 2;", {"'joint'"}
    );
    expectMotionError
    (
        "type harmonic; joint 0; amplitude 1;", {"'frequency'"}
    );
    expectMotionError
    (
        "type wang; joint 0; waveform flapping; amplitude 1; frequency 2;",
        {"'K'"}
    );
    expectMotionError
    (
        "type wang; joint 0; amplitude 1; frequency 2; K 0.5;",
        {"'waveform'"}
    );
    expectMotionError
    (
        "type wangParametrization; Aphi 1; fphi 20; Kphi 0.5;"
        " Aalpha 1; falpha 20; Kalpha 1;",
        {"'jointList'"}
    );
    expectMotionError
    (
        "type wangParametrization; jointList (0 1); fphi 20; Kphi 0.5;"
        " Aalpha 1; falpha 20; Kalpha 1;",
        {"'Aphi'"}
    );
    expectMotionError
    (
        "type wangParametrization; jointList (0 1); Aphi 1; fphi 20;"
        " Kphi 0.5; Aalpha 1; falpha 20;",
        {"'Kalpha'"}
    );
    expectMotionError("type fourier; joint 0; a (1);", {"'frequency'"});
}


TEST(Errors, FrequencyNotPositive)
{
    for (const char* f : {"0", "-1"})
    {
        const std::string fs(f);
        expectMotionError
        (
            "type harmonic; joint 0; amplitude 1; frequency " + fs + ";",
            {"'frequency'", "> 0"}
        );
        expectMotionError
        (
            "type wang; joint 0; waveform pitching; amplitude 1; K 1;"
            " frequency " + fs + ";",
            {"'frequency'", "> 0"}
        );
        expectMotionError
        (
            "type fourier; joint 0; a (1); frequency " + fs + ";",
            {"'frequency'", "> 0"}
        );
        expectMotionError
        (
            "type wangParametrization; jointList (0 1); Aphi 1; Kphi 0.5;"
            " Aalpha 1; falpha 20; Kalpha 1; fphi " + fs + ";",
            {"'fphi'", "> 0"}
        );
        expectMotionError
        (
            "type wangParametrization; jointList (0 1); Aphi 1; Kphi 0.5;"
            " Aalpha 1; fphi 20; Kalpha 1; falpha " + fs + ";",
            {"'falpha'", "> 0"}
        );
    }
}


TEST(Errors, WangKOutOfRange)
{
    // Flapping: 0 < K < 1
    for (const char* K : {"1.2", "1", "0", "-0.5"})
    {
        expectMotionError
        (
            std::string("type wang; joint 0; waveform flapping; amplitude 1;"
            " frequency 2; K ") + K + ";",
            {"'K'", "flapping", "0 < K < 1"}
        );
    }

    // Pitching: K > 0
    for (const char* K : {"-1", "0"})
    {
        expectMotionError
        (
            std::string("type wang; joint 0; waveform pitching; amplitude 1;"
            " frequency 2; K ") + K + ";",
            {"'K'", "pitching", "K > 0"}
        );
    }

    // Valid at the limits' neighbourhood
    EXPECT_NO_THROW
    (
        makeMotion
        (
            "type wang; joint 0; waveform flapping; amplitude 1;"
            " frequency 2; K 0.99;"
        )
    );
    EXPECT_NO_THROW
    (
        makeMotion
        (
            "type wang; joint 0; waveform pitching; amplitude 1;"
            " frequency 2; K 1e-8;"
        )
    );
}


TEST(Errors, WangUnknownWaveform)
{
    expectMotionError
    (
        "type wang; joint 0; waveform heaving; amplitude 1; frequency 2;"
        " K 0.5;",
        {"'waveform'", "heaving", "flapping", "pitching"}
    );
}


TEST(Errors, WangParametrizationBadInput)
{
    // jointList with other than 2 entries
    for (const char* list : {"(3)", "(3 4 5)", "()"})
    {
        expectMotionError
        (
            "type wangParametrization; Aphi 1; fphi 20; Kphi 0.5; Aalpha 1;"
            " falpha 20; Kalpha 1; jointList " + std::string(list) + ";",
            {"'jointList'", "exactly 2"}
        );
    }

    // K ranges name their own keys
    expectMotionError
    (
        "type wangParametrization; jointList (0 1); Aphi 1; fphi 20;"
        " Kphi 1.5; Aalpha 1; falpha 20; Kalpha 1;",
        {"'Kphi'", "0 < Kphi < 1"}
    );
    expectMotionError
    (
        "type wangParametrization; jointList (0 1); Aphi 1; fphi 20;"
        " Kphi 0.5; Aalpha 1; falpha 20; Kalpha -1;",
        {"'Kalpha'", "Kalpha > 0"}
    );

    // Unknown motionType lists the allowed ones
    expectMotionError
    (
        wangParametrizationText("motionType midStartControl_z_PD;"),
        {"'motionType'", "midStartControl_z_PD", "standard", "midStart"}
    );
}


TEST(Errors, FourierBadCoefficients)
{
    expectMotionError
    (
        "type fourier; joint 0; frequency 2; a0 1;", {"'a'", "'b'"}
    );
    expectMotionError
    (
        "type fourier; joint 0; frequency 2; a (1 2); b (1);",
        {"'a'", "'b'", "same length"}
    );
    expectMotionError
    (
        "type fourier; joint 0; frequency 2; a ();", {"'a'", "'b'", "empty"}
    );
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


// * * * * * * * * * * * * * * * imposedMotionList * * * * * * * * * * * * * //

namespace
{

const std::string modelText
(
    "bodies { }\n"
    "imposedMotion\n"
    "{\n"
    "    wing\n"
    "    {\n"
    "        type wangParametrization; jointList (5 1); Aphi 1.309;\n"
    "        fphi 20; Kphi 0.01; Aalpha 0.785; falpha 20; Kalpha 0.01;\n"
    "    }\n"
    "    shoulder { type harmonic; joint 3; amplitude 0.5; frequency 2; }\n"
    "    pitch\n"
    "    {\n"
    "        type wang; joint 0; waveform pitching; amplitude 0.3;\n"
    "        frequency 10; K 2;\n"
    "    }\n"
    "}\n"
);

//- Model with nDoF 1-DoF joints and the given imposedMotion entries
std::string modelWith(const std::string& entries)
{
    return "imposedMotion { " + entries + " }";
}

}


TEST(ImposedMotionList, JointsAscending)
{
    const imposedMotionList list(makeDict(modelText), labelList(7, 1));

    EXPECT_EQ(list.size(), 3);
    EXPECT_EQ(list.joints(), labelList({0, 1, 3, 5}));
    EXPECT_EQ(list[0].name(), "wing");
    EXPECT_EQ(list[2].type(), "wang");
}


TEST(ImposedMotionList, EvaluateWritesOnlyPrescribedEntries)
{
    const dictionary modelDict(makeDict(modelText));
    const imposedMotionList list(modelDict, labelList(7, 1));

    const scalar sentinel = 1234.5;
    scalarField q(7, sentinel), qDot(7, sentinel + 1), qDdot(7, sentinel + 2);

    const scalar t = 0.0123;
    list.evaluate(t, q, qDot, qDdot);

    // Prescribed entries: the motions' values
    auto wing = imposedMotion::New
    (
        "wing", modelDict.subDict("imposedMotion").subDict("wing")
    );
    auto shoulder = imposedMotion::New
    (
        "shoulder", modelDict.subDict("imposedMotion").subDict("shoulder")
    );
    auto pitch = imposedMotion::New
    (
        "pitch", modelDict.subDict("imposedMotion").subDict("pitch")
    );

    const auto expectJoint =
        [&](const label j, const imposedMotion& m, const label i)
        {
            const jointState s = eval(m, i, t);
            EXPECT_EQ(q[j], s.q) << "q[" << j << ']';
            EXPECT_EQ(qDot[j], s.qDot) << "qDot[" << j << ']';
            EXPECT_EQ(qDdot[j], s.qDdot) << "qDdot[" << j << ']';
        };

    expectJoint(5, *wing, 0);
    expectJoint(1, *wing, 1);
    expectJoint(3, *shoulder, 0);
    expectJoint(0, *pitch, 0);

    // The others untouched
    for (const label j : {2, 4, 6})
    {
        EXPECT_EQ(q[j], sentinel) << j;
        EXPECT_EQ(qDot[j], sentinel + 1) << j;
        EXPECT_EQ(qDdot[j], sentinel + 2) << j;
    }
}


TEST(ImposedMotionList, EmptyWithoutSubDictionary)
{
    const imposedMotionList list
    (
        makeDict("bodies { } joints { }"), labelList(4, 1)
    );

    EXPECT_EQ(list.size(), 0);
    EXPECT_TRUE(list.joints().empty());

    scalarField q(4, 1.5), qDot(4, 2.5), qDdot(4, 3.5);
    list.evaluate(0.1, q, qDot, qDdot);
    for (label j = 0; j < 4; ++j)
    {
        EXPECT_EQ(q[j], 1.5);
        EXPECT_EQ(qDot[j], 2.5);
        EXPECT_EQ(qDdot[j], 3.5);
    }

    // Empty sub-dictionary: also empty
    const imposedMotionList list2
    (
        makeDict("imposedMotion { }"), labelList(4, 1)
    );
    EXPECT_EQ(list2.size(), 0);
    EXPECT_TRUE(list2.joints().empty());

    // Default constructed
    const imposedMotionList list3;
    EXPECT_TRUE(list3.joints().empty());
}


TEST(ImposedMotionList, WriteRoundTrips)
{
    const imposedMotionList list(makeDict(modelText), labelList(7, 1));

    OStringStream os;
    os.precision(17);
    list.write(os);

    const imposedMotionList list2(makeDict(os.str()), labelList(7, 1));

    EXPECT_EQ(list2.size(), list.size()) << os.str();
    EXPECT_EQ(list2.joints(), list.joints()) << os.str();

    scalarField q1(7, 0), qDot1(7, 0), qDdot1(7, 0);
    scalarField q2(7, 0), qDot2(7, 0), qDdot2(7, 0);
    list.evaluate(0.0217, q1, qDot1, qDdot1);
    list2.evaluate(0.0217, q2, qDot2, qDdot2);
    for (label j = 0; j < 7; ++j)
    {
        EXPECT_NEAR(q2[j], q1[j], 1e-12);
        EXPECT_NEAR(qDot2[j], qDot1[j], 1e-9);
        EXPECT_NEAR(qDdot2[j], qDdot1[j], 1e-6);
    }
}


TEST(ImposedMotionList, EvaluateChecksStateSize)
{
    const imposedMotionList list(makeDict(modelText), labelList(7, 1));
    scalarField q(5, 0), qDot(5, 0), qDdot(5, 0);

    try
    {
        list.evaluate(0, q, qDot, qDdot);
        ADD_FAILURE() << "no FatalError for a state smaller than the joints";
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find("too small"), std::string::npos) << msg;
    }
}


TEST(Errors, ImposedMotionListJointOutOfRange)
{
    const labelList jointDoF(6, 1);

    for (const char* j : {"-1", "6"})
    {
        SCOPED_TRACE(j);
        expectIOError
        (
            [&]()
            {
                imposedMotionList
                (
                    makeDict
                    (
                        modelWith
                        (
                            "flap { type harmonic; amplitude 1; frequency 2;"
                            " joint " + std::string(j) + "; }"
                        )
                    ),
                    jointDoF
                );
            },
            {"'joint'", "'flap'", std::string("joint ") + j, "0..5"}
        );
    }

    // jointList names its own key
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict(modelWith("wing { " + wangParametrizationText("")
                  + " }")),
                labelList(4, 1)         // jointList (3 4): 4 out of range
            );
        },
        {"'jointList'", "'wing'", "joint 4", "0..3"}
    );
}


TEST(Errors, ImposedMotionListMultiDoFJoint)
{
    // q indices 2, 3, 4 belong to a 3-DoF joint (e.g. spherical)
    const labelList jointDoF({1, 1, 3, 3, 3, 1});

    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict
                (
                    modelWith
                    (
                        "flap { type harmonic; joint 3; amplitude 1;"
                        " frequency 2; }"
                    )
                ),
                jointDoF
            );
        },
        {
            "'joint'", "'flap'", "joint 3",
            "belongs to a joint with 3 degrees of freedom",
            "only 1-DoF joints can be prescribed"
        }
    );

    // The 1-DoF ones are fine
    EXPECT_NO_THROW
    (
        imposedMotionList
        (
            makeDict
            (
                modelWith
                (
                    "flap { type harmonic; joint 5; amplitude 1;"
                    " frequency 2; }"
                )
            ),
            jointDoF
        )
    );
}


TEST(Errors, ImposedMotionListJointPrescribedTwice)
{
    const labelList jointDoF(6, 1);

    // By two entries: both named
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict
                (
                    modelWith
                    (
                        "left { type harmonic; joint 2; amplitude 1;"
                        " frequency 2; }"
                        " right { type wang; joint 2; waveform flapping;"
                        " amplitude 1; frequency 2; K 0.5; }"
                    )
                ),
                jointDoF
            );
        },
        {"joint 2", "prescribed twice", "'left'", "'right'"}
    );

    // Twice in one entry: wangParametrization jointList (2 2)
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict
                (
                    modelWith
                    (
                        "wing { type wangParametrization; jointList (2 2);"
                        " Aphi 1; fphi 20; Kphi 0.5; Aalpha 1; falpha 20;"
                        " Kalpha 1; }"
                    )
                ),
                jointDoF
            );
        },
        {
            "'jointList'", "'wing'", "joint 2", "prescribed twice",
            "appears twice"
        }
    );
}


TEST(Errors, ImposedMotionListNotDictionaries)
{
    // An entry that is not a motion dictionary
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict(modelWith("flap 3;")), labelList(4, 1)
            );
        },
        {"'flap'", "not a dictionary"}
    );

    // imposedMotion itself not a dictionary
    expectIOError
    (
        [&]()
        {
            imposedMotionList
            (
                makeDict("imposedMotion none;"), labelList(4, 1)
            );
        },
        {"'imposedMotion'", "not a dictionary"}
    );
}


// * * * * * * * * * * * * * * * * * * main  * * * * * * * * * * * * * * * * //

int main(int argc, char* argv[])
{
    ::testing::InitGoogleTest(&argc, argv);

    // Bad input must throw (caught and checked by the tests), not exit
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    return RUN_ALL_TESTS();
}


// ************************************************************************* //
