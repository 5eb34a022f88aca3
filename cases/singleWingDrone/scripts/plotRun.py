#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Plots of a single-wing drone run (Allrun calls it at the end of a run).

    scripts/plotRun.py [-case DIR] [-o OUTDIR] [--dict FILE]

Reads the run's flight data, postProcessing/flightData/<start>/flightData.h5
(scripts/flightData.py; restarts append to it), or, for runs without it,
postProcessing/eABAMeshMotion/<startTime>/{joints,bodies}.dat of the case
(the folders of a run and its restarts joined in time order: a restart
folder, whose first row is its first step, replaces the rows of the earlier
folders from that time on), and writes, in OUTDIR (default DIR/plots):

  trajectory.png         (a) x-z trajectory of the drone: x = q_1 (Tx),
                         z = q_0 (Tz), displacement of the surge link from
                         its start;
  forceCoefficients.png  (b) wing force coefficients in the global frame
                             C_xI = F_x/(0.5 rho S U_ref^2), C_zI likewise,
                         against t f (cycles), downstroke shaded (phi
                         decreasing, qDot_2 < 0);
  prescribedJoints.png   (c) q_2 (flapping phi) and q_3 (pitching alpha)
                         against the analytic Wang motion evaluated here
                         from the imposedMotion entries of the run's
                         constant/dynamicMeshDict, and their difference;
  stepTimers.png         (d) the step-timer bar chart
                         (/work/main/scripts/plotStepTimers.py on
                         postProcessing/stepTimers).

Reference values (docs/paper.md section 3):
  S = pi/4 c_r R = R cbar (planform area of the wing);
  U_ref = 4 f A_phi R2,  R2 = sqrt(int c r^2 dr / S), the radius of
  gyration of the planform ABOUT THE FLAPPING AXIS: r is measured from the
  axis, from R0 (root) to R0 + R (tip), c = c(r - R0) of wingGeometry.py.
  Closed form for the semi-ellipse: R2^2 = R0^2 + 8/(3 pi) R0 R + R^2/4,
  R2 = 45.67 mm, U_ref = 4.783 m/s (r from the root instead: R2 = R/2).
  f, A_phi from the flapping entry, rho from rhoInf of the dictionary.

Times: the load in the bodies.dat row of time t_k is the one the model
used for the step to t_k, computed from the flow at the start of that step
(t_{k-1}); it is plotted at t_{k-1}.

Prints a summary (rows, time span, final position, mean coefficients over
the complete cycles, largest prescribed-joint deviation).  Exit status
non-zero if the data are missing.

Uses Debian's python (/usr/bin/python3) with numpy and matplotlib (Agg).
"""

import argparse
import math
import os
import re
import subprocess
import sys

import numpy as np

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import wingGeometry as geo  # noqa: E402

PLOT_STEP_TIMERS = os.path.normpath(
    os.path.join(HERE, "..", "..", "..", "scripts", "plotStepTimers.py"))
sys.path.insert(0, os.path.dirname(PLOT_STEP_TIMERS))
import flightData  # noqa: E402


# --------------------------------------------------------------------------
# Reference length and velocity

def radiusOfGyration():
    """R2 = sqrt(int_{R0}^{R0+R} c(r - R0) r^2 dr / S), r from the flapping
    axis (closed form; checked against the quadrature in checkR2)."""
    R0, R = geo.R0, geo.R
    return math.sqrt(R0**2 + 8.0/(3.0*math.pi)*R0*R + 0.25*R**2)


def radiusOfGyrationQuadrature(n=200001):
    """The same integral by the trapezoidal rule in tau, r = R0 + R sin(tau)
    (smooth integrand despite the square-root tip)."""
    tau = np.linspace(0.0, 0.5*math.pi, n)
    rho = geo.R*np.sin(tau)
    w = geo.chord(rho)*(geo.R0 + rho)**2*geo.R*np.cos(tau)
    integral = np.trapz(w, tau)
    return math.sqrt(integral/geo.planformArea())


# --------------------------------------------------------------------------
# Minimal OpenFOAM dictionary reader (enough for dynamicMeshDict)

def readFoamDict(path):
    """Nested dict of an OpenFOAM dictionary file: sub-dictionaries as dicts,
    entries as lists of tokens (strings)."""
    with open(path) as f:
        text = f.read()
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    tokens = re.findall(r'"[^"]*"|[{}();]|[^\s{}();"]+', text)
    pos = 0

    def parse():
        nonlocal pos
        d = {}
        while pos < len(tokens):
            t = tokens[pos]
            if t == "}":
                pos += 1
                return d
            key = t
            pos += 1
            if pos < len(tokens) and tokens[pos] == "{":
                pos += 1
                d[key] = parse()
                continue
            value = []
            depth = 0
            while pos < len(tokens):
                t = tokens[pos]
                pos += 1
                if t == "(":
                    depth += 1
                elif t == ")":
                    depth -= 1
                elif t == ";" and depth == 0:
                    break
                value.append(t)
            d[key] = value
        return d

    return parse()


def wangMotion(entry):
    """Analytic Wang kinematics of an imposedMotion entry (type wang):
    flapping q = offset + A/asin(K) asin(K cos(theta)),
    pitching q = offset + A/tanh(K) tanh(K sin(theta)),
    theta = 2 pi f t + phase.  Returns f(t) -> (q, qDot, qDdot)."""
    if entry["type"][0] != "wang":
        raise ValueError("imposedMotion entry of type %s, not wang"
                         % entry["type"][0])
    waveform = entry["waveform"][0]
    A = float(entry["amplitude"][0])
    f = float(entry["frequency"][0])
    K = float(entry["K"][0])
    phase = float(entry.get("phase", ["0"])[0])
    offset = float(entry.get("offset", ["0"])[0])
    w = 2.0*math.pi*f

    def evaluate(t):
        theta = w*np.asarray(t, dtype=float) + phase
        c, s = np.cos(theta), np.sin(theta)
        if waveform == "flapping":
            S = A/math.asin(K)
            u, du, ddu = K*c, -K*w*s, -w*w*K*c
            one = 1.0 - u*u
            q = offset + S*np.arcsin(u)
            qDot = S*du/np.sqrt(one)
            qDdot = S/np.sqrt(one)*(ddu + u*du*du/one)
        else:
            S = A/math.tanh(K)
            v, dv, ddv = K*s, K*w*c, -w*w*K*s
            th = np.tanh(v)
            sech2 = 1.0/np.cosh(v)**2
            q = offset + S*th
            qDot = S*dv*sech2
            qDdot = S*sech2*(ddv - 2.0*th*dv*dv)
        return q, qDot, qDdot

    evaluate.amplitude = A
    evaluate.frequency = f
    evaluate.waveform = waveform
    return evaluate


def imposedJoints(coeffs):
    """{joint index: wang evaluator} of the imposedMotion entries."""
    joints = {}
    for name, entry in coeffs.get("imposedMotion", {}).items():
        if isinstance(entry, dict) and "joint" in entry:
            ev = wangMotion(entry)
            ev.name = name
            joints[int(entry["joint"][0])] = ev
    return joints


# --------------------------------------------------------------------------
# Per-step tables, joined over restarts

def readTable(path):
    """(columns, rows) of a joints.dat/bodies.dat file: the first comment
    line starting '# time' names the columns."""
    columns = None
    rows = []
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "#":
                if columns is None and len(words) > 1 and words[1] == "time":
                    columns = words[1:]
                continue
            rows.append([float(w) for w in words])
    if columns is None:
        sys.exit("plotRun: %s has no '# time ...' header" % path)
    data = np.array(rows, dtype=float).reshape(-1, len(columns))
    return columns, data


def startFolders(base):
    """Start-time folders of a postProcessing/<name> directory, in order."""
    if not os.path.isdir(base):
        return []
    found = []
    for d in os.listdir(base):
        try:
            found.append((float(d), os.path.join(base, d)))
        except ValueError:
            pass
    return sorted(found)


def joinedTable(base, fileName, keepEarlierAtStart):
    """The rows of base/<t>/fileName of all start folders t joined: a later
    folder replaces the rows from its start time on; its first row (the
    start time) is dropped when keepEarlierAtStart and an earlier row
    exists."""
    columns = None
    data = None
    for t0, folder in startFolders(base):
        path = os.path.join(folder, fileName)
        if not os.path.isfile(path):
            continue
        cols, rows = readTable(path)
        if columns is None:
            columns, data = cols, rows
            continue
        if cols != columns:
            sys.exit("plotRun: %s: columns differ from the first folder"
                     % path)
        eps = 1e-9*max(abs(t0), 1e-300) + 1e-15
        if keepEarlierAtStart and np.any(np.abs(data[:, 0] - t0) <= eps):
            data = np.vstack([data[data[:, 0] <= t0 + eps],
                              rows[rows[:, 0] > t0 + eps]])
        else:
            data = np.vstack([data[data[:, 0] < t0 - eps], rows])
    return columns, data


# --------------------------------------------------------------------------

def flightDataTables(case):
    """The joints.dat and bodies.dat tables (columns, rows) from the run's
    flightData.h5, or None without one.  The loads of a row are those of
    the step that ends at its time, as in bodies.dat."""
    if flightData.find(case) is None:
        return None
    _, d = flightData.load(case)
    t = d["time"][:, None]
    q, qDot, qDdot = d["joints/q"], d["joints/qDot"], d["joints/qDdot"]
    jcols, jdata = ["time"], [t]
    for i in range(q.shape[1]):
        jcols += ["q_%d" % i, "qDot_%d" % i, "qDdot_%d" % i]
        jdata += [q[:, i:i+1], qDot[:, i:i+1], qDdot[:, i:i+1]]
    if "joints/tau" in d:
        # column names tau_<q index>, as the dataset's columns
        import h5py
        with h5py.File(flightData.find(case), "r") as f:
            prescribed = [c.split("_")[1]
                          for c in f["joints/tau"].attrs["columns"].split()]
        for k, qi in enumerate(prescribed):
            jcols += ["tau_%s" % qi, "power_%s" % qi]
            jdata += [d["joints/tau"][:, k:k+1], d["joints/power"][:, k:k+1]]
    bcols, bdata = ["time"], [t]
    bodies = sorted({k.split("/")[1] for k in d if k.startswith("bodies/")})
    for b in bodies:
        for name, key in (("c", "position"), ("F", "force"),
                          ("M", "moment")):
            for c, v in zip("xyz", d["bodies/%s/%s" % (b, key)].T):
                bcols.append("%s:%s%s" % (b, name, c))
                bdata.append(v[:, None])
    return jcols, np.hstack(jdata), bcols, np.hstack(bdata)


def shadeDownstrokes(ax, t, qDot):
    """Shade the intervals where phi decreases (qDot < 0)."""
    down = qDot < 0
    if not down.any():
        return
    edges = np.flatnonzero(np.diff(down.astype(int))) + 1
    bounds = np.concatenate([[0], edges, [len(t)]])
    first = True
    for a, b in zip(bounds[:-1], bounds[1:]):
        if down[a]:
            ax.axvspan(t[a], t[min(b, len(t) - 1)], color="0.88", lw=0,
                       label="downstroke" if first else None)
            first = False


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1],
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("-case", default=".", help="case directory")
    ap.add_argument("-o", "--output", default=None,
                    help="output directory (default CASE/plots; a relative "
                         "path is relative to the working directory)")
    ap.add_argument("--dict", default=None,
                    help="multibody dictionary (default "
                         "CASE/constant/dynamicMeshDict)")
    args = ap.parse_args()

    case = args.case
    out = args.output or os.path.join(case, "plots")
    os.makedirs(out, exist_ok=True)

    dictPath = args.dict or os.path.join(case, "constant", "dynamicMeshDict")
    meshDict = readFoamDict(dictPath)
    coeffs = meshDict.get("eABAMeshMotionCoeffs", meshDict)
    joints = imposedJoints(coeffs)
    rho = float(coeffs.get("rhoInf", ["1.2"])[0])

    base = os.path.join(case, "postProcessing", "eABAMeshMotion")
    tables = flightDataTables(case)
    if tables is not None:
        jcols, J, bcols, B = tables
        source = "flightData.h5"
        print("plotRun: reading %s" % flightData.find(case))
    else:
        if not startFolders(base):
            sys.exit("plotRun: no %s/<time>/joints.dat and no flightData.h5"
                     % base)
        jcols, J = joinedTable(base, "joints.dat", keepEarlierAtStart=False)
        bcols, B = joinedTable(base, "bodies.dat", keepEarlierAtStart=True)
        source = "joints.dat: 12 digits"
    jc = {c: i for i, c in enumerate(jcols)}
    bc = {c: i for i, c in enumerate(bcols)}
    t = J[:, 0]

    flap = joints.get(2)
    f = flap.frequency if flap else 20.0
    Aphi = flap.amplitude if flap else 75.0*math.pi/180.0
    S = geo.planformArea()
    R2 = radiusOfGyration()
    Uref = 4.0*f*Aphi*R2
    qref = 0.5*rho*S*Uref**2

    print("plotRun: %d steps, t = %.6g ... %.6g s (%.3f cycles), %d restart "
          "folder(s)" % (len(t) - 1, t[0], t[-1], (t[-1] - t[0])*f,
                         len(startFolders(base)) - 1))
    print("plotRun: S = %.6g m^2, R2 = %.6g m (about the flapping axis; "
          "quadrature %.6g), U_ref = 4 f A_phi R2 = %.6g m/s, rho = %g"
          % (S, R2, radiusOfGyrationQuadrature(), Uref, rho))

    # (a) trajectory
    x = J[:, jc["q_1"]]
    z = J[:, jc["q_0"]]
    fig, ax = plt.subplots(figsize=(6, 5))
    ax.plot(1e3*x, 1e3*z, "-", lw=1.2)
    ax.plot(1e3*x[0], 1e3*z[0], "o", label="t = %.4g s" % t[0])
    ax.plot(1e3*x[-1], 1e3*z[-1], "s", label="t = %.4g s" % t[-1])
    ax.set_xlabel("x = q_1 (Tx) [mm]")
    ax.set_ylabel("z = q_0 (Tz) [mm]")
    ax.set_title("Single-wing drone: trajectory of the surge link")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "trajectory.png"), dpi=120)
    plt.close(fig)
    print("plotRun: final x = %.6g m, z = %.6g m, xDot = %.6g, zDot = %.6g "
          "m/s" % (x[-1], z[-1], J[-1, jc["qDot_1"]], J[-1, jc["qDot_0"]]))

    # (b) force coefficients: the row of t_k holds the load of the flow at
    # t_{k-1}
    if "wing:Fx" in bc and len(B) > 1:
        tF = B[:-1, 0]
        Cx = B[1:, bc["wing:Fx"]]/qref
        Cz = B[1:, bc["wing:Fz"]]/qref
        # the phase of the stroke at the load times
        qDot2 = np.interp(tF, t, J[:, jc["qDot_2"]]) if "qDot_2" in jc \
            else np.zeros_like(tF)
        fig, ax = plt.subplots(figsize=(8, 4.5))
        shadeDownstrokes(ax, f*tF, qDot2)
        ax.plot(f*tF, Cx, label="C_xI")
        ax.plot(f*tF, Cz, label="C_zI")
        ax.axhline(0, color="k", lw=0.5)
        # The impulsive start (the flow at rest, the wing at full speed with
        # -midStroke) gives coefficients of order 1e3 for a few steps: the
        # range is clipped to median +- 10 scaled median absolute deviations
        # (at least the 2-98 percentile range) when the spikes would hide
        # the rest; the full range is printed
        both = np.concatenate([Cx, Cz])
        med = np.median(both)
        spread = 10*1.4826*np.median(np.abs(both - med)) + 1e-12
        p2, p98 = np.percentile(both, [2, 98])
        lo, hi = min(med - spread, p2), max(med + spread, p98)
        if len(both) > 40 and (both.min() < lo or both.max() > hi):
            pad = 0.05*(hi - lo)
            ax.set_ylim(lo - pad, hi + pad)
            ax.text(0.01, 0.01, "range clipped: C from %.3g to %.3g"
                    % (both.min(), both.max()), transform=ax.transAxes,
                    fontsize=8, va="bottom")
        print("plotRun: C_xI from %.4g to %.4g, C_zI from %.4g to %.4g"
              % (Cx.min(), Cx.max(), Cz.min(), Cz.max()))
        ax.set_xlabel("t f [cycles]")
        ax.set_ylabel("C = F / (0.5 rho S U_ref^2)")
        ax.set_title("Wing force coefficients (global frame), U_ref = %.3f "
                     "m/s" % Uref)
        ax.grid(True, alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(out, "forceCoefficients.png"), dpi=120)
        plt.close(fig)
        nCycles = int(math.floor((tF[-1] - t[0])*f + 1e-9))
        if nCycles >= 1:
            sel = tF <= t[0] + nCycles/f
            w = np.gradient(tF[sel]) if sel.sum() > 1 else np.ones(1)
            print("plotRun: mean C_xI = %.6g, C_zI = %.6g over %d cycle(s)"
                  % (np.sum(w*Cx[sel])/np.sum(w), np.sum(w*Cz[sel])/np.sum(w),
                     nCycles))
        print("plotRun: last C_xI = %.6g, C_zI = %.6g" % (Cx[-1], Cz[-1]))

    # (c) prescribed joints against the analytic motion
    if joints:
        fig, axes = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
        worst = 0.0
        for qi, ev in sorted(joints.items()):
            q, _, _ = ev(t)
            sim = J[:, jc["q_%d" % qi]]
            label = "q_%d %s" % (qi, ev.name)
            axes[0].plot(f*t, np.degrees(q), "-", lw=1,
                         label=label + " analytic")
            axes[0].plot(f*t, np.degrees(sim), ".", ms=3,
                         markevery=max(1, len(t)//200),
                         label=label + " eABAMeshMotion")
            err = np.abs(sim - q)
            worst = max(worst, err.max()/ev.amplitude)
            axes[1].semilogy(f*t, np.maximum(err, 1e-18), lw=1,
                             label="|q_%d - analytic|" % qi)
        axes[0].set_ylabel("angle [deg]")
        axes[0].grid(True, alpha=0.3)
        axes[0].legend(fontsize=7)
        axes[1].set_ylabel("|difference| [rad]")
        axes[1].set_xlabel("t f [cycles]")
        axes[1].grid(True, alpha=0.3)
        axes[1].legend(fontsize=7)
        axes[0].set_title("Prescribed joints against the Wang kinematics "
                          "(%s)" % source)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "prescribedJoints.png"), dpi=120)
        plt.close(fig)
        print("plotRun: prescribed joints: max |q - analytic|/amplitude = "
              "%.3g" % worst)

    # (d) step timers
    timers = os.path.join(case, "postProcessing", "stepTimers")
    if os.path.isdir(timers):
        rc = subprocess.call([sys.executable, PLOT_STEP_TIMERS, timers, "-o",
                              os.path.join(out, "stepTimers.png"), "-l",
                              os.path.basename(os.path.abspath(case))])
        if rc != 0:
            print("plotRun: plotStepTimers.py failed (exit %d)" % rc)
            return rc
    print("plotRun: wrote %s/{trajectory,forceCoefficients,prescribedJoints,"
          "stepTimers}.png" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
