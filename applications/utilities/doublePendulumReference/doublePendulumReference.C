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
    doublePendulumReference

Group
    grpFlapFoamUtilities

Description
    Independent Lagrangian reference for the double pendulum of Poletti et
    al. (section 4, validation of the eABA): two massless rods l1, l2 with
    point masses m1, m2 at their ends, in gravity g, in a vertical plane.
    Written with Eigen and its own Dormand-Prince 5(4) integrator; it uses
    none of OpenFOAM's rigid-body or ODE code (only argList and the file
    streams of libOpenFOAM).

    Coordinates: absolute angles th1, th2 of the rods from the downward
    vertical; mass positions x_k (horizontal), z_k (up)
        x1 = l1 sin th1,             z1 = -l1 cos th1
        x2 = x1 + l2 sin th2,        z2 = z1 - l2 cos th2

    Lagrangian L = T - V:
        T = 1/2 (m1 + m2) l1^2 th1d^2 + 1/2 m2 l2^2 th2d^2
          + m2 l1 l2 cos(th1 - th2) th1d th2d
        V = (m1 + m2) g l1 (1 - cos th1) + m2 g l2 (1 - cos th2)
    (V = 0 and so E = T + V = 0 at rest hanging down.)

    Lagrange's equations, M(th) thdd + C(th, thd) = Q:
        M = | (m1 + m2) l1^2         m2 l1 l2 cos(th1-th2) |
            | m2 l1 l2 cos(th1-th2)  m2 l2^2               |
        C = |  m2 l1 l2 sin(th1-th2) th2d^2 + (m1 + m2) g l1 sin th1 |
            | -m2 l1 l2 sin(th1-th2) th1d^2 + m2 g l2 sin th2        |

    Generalised forces: with torque tau1 in joint 1 (ground -> rod 1) and
    tau2 in joint 2 (rod 1 -> rod 2), the virtual work is
        tau1 dth1 + tau2 (dth2 - dth1)   so   Q1 = tau1 - tau2, Q2 = tau2.
    In OpenFOAM's tree the joint coordinates are relative, q0 = th1 and
    q1 = th2 - th1, and the forces conjugate to (q0, q1) are
    (Q1 + Q2, Q2) = (tau1, tau2): the same joint torques.

    Mode \c prescribed (joint 1 driven, joint 2 free, tau2 = 0):
        th1(t)   =  A cos(w t) - A,     w = 2 pi f
        th1d(t)  = -A w sin(w t)
        th1dd(t) = -A w^2 cos(w t)                  (exact derivatives)
      second equation divided by m2 l2 (the paper's reference):
        l2 th2dd = l1 th1d^2 sin(th1 - th2) - l1 th1dd cos(th1 - th2)
                 - g sin th2
      the torque joint 1 needs, the first equation with Q1 = tau1:
        tau1 = (m1 + m2) l1^2 th1dd + m2 l1 l2 cos(th1 - th2) th2dd
             + m2 l1 l2 sin(th1 - th2) th2d^2 + (m1 + m2) g l1 sin th1
      integrated state (th2, th2d, W) with the work of the drive
        dW/dt = tau1 th1d,  so that E(t) - E(0) = W(t) (checked on output).

    Mode \c free (tau1 = tau2 = 0): state (th1, th2, th1d, th2d),
        thdd = -M^-1 C   (2x2 Cholesky solve, Eigen);  E is conserved.

    Output file: comment lines starting with '#', among them
        # parameters l1 .. l2 .. m1 .. m2 .. g .. A .. f .. mode ..
        # time theta1 theta2 theta2rel theta1Dot theta2Dot theta1Ddot
          theta2Ddot tau1 E W
    and one row per output time (t = 0, writeInterval, ..., endTime):
        theta2rel = th2 - th1 (OpenFOAM's q of joint 2), tau1 [N m] (0 in
        free mode), E = T + V [J], W = work of tau1 [J] (0 in free mode).

Usage
    \b doublePendulumReference [OPTION]

    Options (SI units, angles in rad; defaults are the paper's pendulum):
      - \par -mode prescribed|free (default prescribed)
      - \par -l1, -l2 (0.1, 0.2), -m1, -m2 (0.5, 0.5), -g (9.81)
      - \par -A (57 deg = 0.994838 rad), -f (2 Hz)         prescribed mode
      - \par -theta1, -theta2, -theta1Dot, -theta2Dot (0)  initial state,
             absolute angles (theta1, theta1Dot: free mode only)
      - \par -state FILE  initial state from an OpenFOAM
             rigidBodyMotionState file (relative q, qDot of the two joints);
             in prescribed mode only q[1], qDot[1] are used
      - \par -endTime (2), -writeInterval (1e-3)
      - \par -relTol, -absTol (1e-12, 1e-12)
      - \par -output FILE (doublePendulumReference.dat)

    Example:
    \verbatim
    doublePendulumReference -mode free -state 0/uniform/rigidBodyMotionState \
        -endTime 2 -output reference/free.dat
    \endverbatim

\*---------------------------------------------------------------------------*/

#include <Eigen/Core>

#include "argList.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "dictionary.H"
#include "scalarField.H"
#include "mathematicalConstants.H"
#include "Enum.H"

#include "doublePendulum.H"
#include "dormandPrince45.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

enum class pendulumMode { prescribed, free };

const Enum<pendulumMode> pendulumModeNames
({
    { pendulumMode::prescribed, "prescribed" },
    { pendulumMode::free, "free" },
});


//- Read an option, checking it lies in [minVal, maxVal]
scalar getOption
(
    const argList& args,
    const word& name,
    const scalar deflt,
    const scalar minVal = -GREAT,
    const scalar maxVal = GREAT
)
{
    const scalar val = args.getOrDefault<scalar>(name, deflt);
    if (!(val >= minVal && val <= maxVal))
    {
        FatalErrorInFunction
            << "Option -" << name << " = " << val << " must be ";
        if (minVal == VSMALL && maxVal == GREAT)
        {
            FatalError<< "positive";
        }
        else
        {
            FatalError<< "in [" << minVal << ", " << maxVal << "]";
        }
        FatalError<< exit(FatalError);
    }
    return val;
}


//- Read q[i], qDot[i] of joint i from an OpenFOAM rigidBodyMotionState
void readState
(
    const fileName& file,
    scalarField& q,
    scalarField& qDot
)
{
    IFstream is(file);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot open state file " << is.name() << exit(FatalError);
    }
    const dictionary dict(is);

    q = dict.get<scalarField>("q");
    qDot = dict.getOrDefault<scalarField>("qDot", scalarField(q.size(), 0));

    if (q.size() != 2 || qDot.size() != 2)
    {
        FatalIOErrorInFunction(dict)
            << "Expected q and qDot of 2 joints, got q " << q
            << ", qDot " << qDot << exit(FatalIOError);
    }
}

typedef doublePendulum::vector2 vector2;
typedef dormandPrince45::vector vectorN;


//- Add the utility's note and options
void addOptions()
{
    argList::addNote
    (
        "Lagrangian reference solution of the double pendulum"
        " (Eigen + Dormand-Prince 5(4)); see the source header for the"
        " equations and the output columns"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::noCheckProcessorDirectories();

    argList::addOption("mode", "prescribed|free", "default: prescribed");
    argList::addOption("l1", "m", "rod 1 length (default 0.1)");
    argList::addOption("l2", "m", "rod 2 length (default 0.2)");
    argList::addOption("m1", "kg", "mass at the end of rod 1 (default 0.5)");
    argList::addOption("m2", "kg", "mass at the end of rod 2 (default 0.5)");
    argList::addOption("g", "m/s^2", "gravity (default 9.81)");
    argList::addOption("A", "rad", "drive amplitude (default 57 deg)");
    argList::addOption("f", "Hz", "drive frequency (default 2)");
    argList::addOption("theta1", "rad", "initial th1, free mode (0)");
    argList::addOption("theta2", "rad", "initial th2, absolute (0)");
    argList::addOption("theta1Dot", "rad/s", "initial th1d, free mode (0)");
    argList::addOption("theta2Dot", "rad/s", "initial th2d, absolute (0)");
    argList::addOption
    (
        "state",
        "file",
        "initial state from a rigidBodyMotionState (relative q, qDot)"
    );
    argList::addOption("endTime", "s", "end time (default 2)");
    argList::addOption("writeInterval", "s", "output interval (1e-3)");
    argList::addOption("relTol", "value", "relative tolerance (1e-12)");
    argList::addOption("absTol", "value", "absolute tolerance (1e-12)");
    argList::addOption("output", "file", "(doublePendulumReference.dat)");
}


//- The settings: every option but the initial state, read and checked
struct pendulumSettings
{
    const pendulumMode mode;
    const bool prescribed;
    const scalar l1;
    const scalar l2;
    const scalar m1;
    const scalar m2;
    const scalar g;
    const scalar A;
    const scalar f;
    const scalar endTime;
    const scalar writeInterval;
    const scalar relTol;
    const scalar absTol;
    const fileName output;
    const scalar omega;

    explicit pendulumSettings(const argList& args)
    :
        mode
        (
            pendulumModeNames.get
            (
                args.getOrDefault<word>("mode", "prescribed")
            )
        ),
        prescribed(mode == pendulumMode::prescribed),
        l1(getOption(args, "l1", 0.1, VSMALL)),
        l2(getOption(args, "l2", 0.2, VSMALL)),
        m1(getOption(args, "m1", 0.5, 0)),
        m2(getOption(args, "m2", 0.5, VSMALL)),
        g(getOption(args, "g", 9.81)),
        A(getOption(args, "A", 57*constant::mathematical::pi/180)),
        f(getOption(args, "f", 2, 0)),
        endTime(getOption(args, "endTime", 2, VSMALL)),
        writeInterval(getOption(args, "writeInterval", 1e-3, VSMALL)),
        relTol(getOption(args, "relTol", 1e-12, 0, 1)),
        absTol(getOption(args, "absTol", 1e-12, 0, 1)),
        output
        (
            args.getOrDefault<fileName>
            (
                "output",
                "doublePendulumReference.dat"
            )
        ),
        omega(constant::mathematical::twoPi*f)
    {
        if (relTol <= 0 && absTol <= 0)
        {
            FatalErrorInFunction
                << "-relTol and -absTol cannot both be 0" << exit(FatalError);
        }
    }

    //- Prescribed motion of joint 1 with exact derivatives
    void drive(const scalar t, scalar& th, scalar& thd, scalar& thdd) const
    {
        th = A*std::cos(omega*t) - A;
        thd = -A*omega*std::sin(omega*t);
        thdd = -A*omega*omega*std::cos(omega*t);
    }
};


//- The initial integrated state: (th2, th2d, W) prescribed, (th1, th2,
//- th1d, th2d) free, from the drive, -state and the -theta options
vectorN initialState(const argList& args, const pendulumSettings& s)
{
    // Absolute angles
    scalar th10 = 0, th1d0 = 0, th20 = 0, th2d0 = 0;
    if (s.prescribed)
    {
        scalar th1dd0;
        s.drive(0, th10, th1d0, th1dd0);
    }

    if (args.found("state"))
    {
        scalarField q, qDot;
        readState(args.get<fileName>("state"), q, qDot);
        if (!s.prescribed)
        {
            th10 = q[0];
            th1d0 = qDot[0];
        }
        th20 = th10 + q[1];
        th2d0 = th1d0 + qDot[1];
    }
    if (!s.prescribed)
    {
        args.readIfPresent("theta1", th10);
        args.readIfPresent("theta1Dot", th1d0);
    }
    else if (args.found("theta1") || args.found("theta1Dot"))
    {
        FatalErrorInFunction
            << "-theta1/-theta1Dot are set by the drive in prescribed mode"
            << exit(FatalError);
    }
    args.readIfPresent("theta2", th20);
    args.readIfPresent("theta2Dot", th2d0);

    vectorN y;
    if (s.prescribed)
    {
        y.resize(3);
        y << th20, th2d0, 0;
    }
    else
    {
        y.resize(4);
        y << th10, th20, th1d0, th2d0;
    }

    return y;
}


//- The output file: header, one row per output time, and the energy
//- balance max |E - E0 - W| over the rows
class referenceTable
{
    const pendulumSettings& s_;
    const doublePendulum& model_;
    OFstream os_;
    scalar E0_;
    scalar maxEnergyError_;

    //- Create the folder of the output file; return the file
    static const fileName& makePath(const fileName& output);

    //- Write the comment lines
    void writeHeader();

public:

    //- Open the file (fatal if it cannot) and write the header
    referenceTable(const pendulumSettings& s, const doublePendulum& model);

    //- Write the row of time t, integrated state y
    void writeRow(const scalar t, const vectorN& y);

    //- Energy at t = 0 [J]
    scalar E0() const
    {
        return E0_;
    }

    //- Largest |E - E0 - W| over the rows written [J]
    scalar maxEnergyError() const
    {
        return maxEnergyError_;
    }
};


const fileName& referenceTable::makePath(const fileName& output)
{
    if (!output.path().empty() && !isDir(output.path()))
    {
        mkDir(output.path());
    }
    return output;
}


void referenceTable::writeHeader()
{
    os_ << "# doublePendulumReference: Lagrangian double pendulum,"
        << " Dormand-Prince 5(4), relTol " << s_.relTol
        << " absTol " << s_.absTol << nl
        << "# angles from the downward vertical [rad]; theta2 absolute,"
        << " theta2rel = theta2 - theta1; tau1 [N m]; E, W [J]" << nl
        << "# parameters mode " << pendulumModeNames[s_.mode]
        << " l1 " << s_.l1 << " l2 " << s_.l2
        << " m1 " << s_.m1 << " m2 " << s_.m2
        << " g " << s_.g << " A " << (s_.prescribed ? s_.A : 0)
        << " f " << (s_.prescribed ? s_.f : 0) << nl
        << "# time theta1 theta2 theta2rel theta1Dot theta2Dot"
        << " theta1Ddot theta2Ddot tau1 E W" << nl;
}


referenceTable::referenceTable
(
    const pendulumSettings& s,
    const doublePendulum& model
)
:
    s_(s),
    model_(model),
    os_(makePath(s.output)),
    E0_(0),
    maxEnergyError_(0)
{
    if (!os_.good())
    {
        FatalErrorInFunction
            << "Cannot open " << s_.output << " for writing"
            << exit(FatalError);
    }
    os_.precision(16);

    writeHeader();
}


void referenceTable::writeRow(const scalar t, const vectorN& y)
{
    vector2 th, thd, thdd;
    scalar tau1 = 0, W = 0;
    if (s_.prescribed)
    {
        s_.drive(t, th(0), thd(0), thdd(0));
        th(1) = y(0);
        thd(1) = y(1);
        thdd(1) = model_.theta2Ddot(th, thd(0), thdd(0));
        tau1 = model_.tau1(th, thd, thdd);
        W = y(2);
    }
    else
    {
        th = y.head<2>();
        thd = y.tail<2>();
        thdd = model_.freeAcceleration(th, thd);
    }
    const scalar E = model_.energy(th, thd);
    if (t == 0)
    {
        E0_ = E;
    }
    maxEnergyError_ = std::max(maxEnergyError_, std::abs(E - E0_ - W));

    os_ << t << ' ' << th(0) << ' ' << th(1) << ' ' << th(1) - th(0)
        << ' ' << thd(0) << ' ' << thd(1)
        << ' ' << thdd(0) << ' ' << thdd(1)
        << ' ' << tau1 << ' ' << E << ' ' << W << nl;
}


//- Integrate y from 0 to endTime, a row at t = 0 and every writeInterval;
//- return the number of intervals written
label integrate
(
    const pendulumSettings& s,
    const doublePendulum& model,
    dormandPrince45& solver,
    referenceTable& table,
    vectorN& y
)
{
    // prescribed: y = (th2, th2d, W)
    auto rhsPrescribed =
        [&model, &s](const scalar t, const vectorN& y, vectorN& dydt)
    {
        scalar th1, th1d, th1dd;
        s.drive(t, th1, th1d, th1dd);
        const vector2 th(th1, y(0));
        const scalar th2dd = model.theta2Ddot(th, th1d, th1dd);
        const scalar tau1 =
            model.tau1(th, vector2(th1d, y(1)), vector2(th1dd, th2dd));
        dydt(0) = y(1);
        dydt(1) = th2dd;
        dydt(2) = tau1*th1d;
    };

    // free: y = (th1, th2, th1d, th2d)
    auto rhsFree = [&model](const scalar, const vectorN& y, vectorN& dydt)
    {
        const vector2 thdd =
            model.freeAcceleration(y.head<2>(), y.tail<2>());
        dydt.head<2>() = y.tail<2>();
        dydt.tail<2>() = thdd;
    };

    const label nWrite = std::ceil(s.endTime/s.writeInterval - 1e-9);
    table.writeRow(0, y);
    scalar t = 0;
    for (label i = 1; i <= nWrite; ++i)
    {
        const scalar tNext = std::min(i*s.writeInterval, s.endTime);
        if (s.prescribed)
        {
            solver.integrate(rhsPrescribed, t, tNext, y);
        }
        else
        {
            solver.integrate(rhsFree, t, tNext, y);
        }
        t = tNext;
        table.writeRow(t, y);
    }

    return nWrite;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    addOptions();

    argList args(argc, argv);

    const pendulumSettings s(args);

    vectorN y(initialState(args, s));

    const doublePendulum model(s.l1, s.l2, s.m1, s.m2, s.g);

    referenceTable table(s, model);

    dormandPrince45 solver(s.relTol, s.absTol);

    const label nWrite = integrate(s, model, solver, table, y);

    Info<< "Mode " << pendulumModeNames[s.mode] << ": " << nWrite + 1
        << " rows written to " << s.output << nl
        << "Dormand-Prince 5(4): " << solver.nAccepted() << " steps, "
        << solver.nRejected() << " rejected, " << solver.nEval()
        << " evaluations" << nl
        << "Energy balance max |E - E0 - W| = " << table.maxEnergyError()
        << " J (E0 = " << table.E0() << " J)" << nl
        << "\nEnd\n" << endl;

    return 0;
}


// ************************************************************************* //
