# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Double pendulum: compare rigidBodySimulate (eABA) with the Lagrangian
reference (doublePendulumReference) and run the case's checks.

Used by the case's Alltest (``flapfoam double_pendulum check``), by
flapfoam.plots.double_pendulum (import) and for the README table
(``flapfoam double_pendulum table``).  Paths are relative to the case
directory: -case DIR, default the folder it is run in.

Inputs (written by Allrun):
    runs/<integrator>/postProcessing/rigidBodySimulate/0/joints.dat
        # time q_0 qDot_0 qDdot_0 q_1 qDot_1 qDdot_1 tau_0 power_0
    runs/free/postProcessing/rigidBodySimulate/0/joints.dat
        the same without tau_0, power_0
    reference/prescribed.dat, reference/free.dat
        doublePendulumReference output (see its source header)

Joint map: q_0 = theta1, q_1 = theta2 - theta1 (relative); the reference
uses absolute angles from the downward vertical.

Metrics (all maxima over the output rows in the window):
    theta1       max |q_0 - theta1_ref|                       [0, 2] s, rad
    theta2       max |(q_0 + q_1) - theta2_ref|               [0, 1] s, rad
    tau1         max |tau_0 - tau1_ref| / max |tau1_ref|      [0, 1] s
    energy       max |E - E(0) - W| / max |W|                 [0, 2] s
                 E: kinetic + potential energy of the point masses from
                 q, qDot of joints.dat; W: work of the drive, the integral
                 of tau_0*qDot_0 by Simpson's rule over pairs of rows (so
                 evaluated at every other row)
    free energy  max |E - E(0)| / E(0)  (E = 0 at rest hanging down)  [0, 2] s
    free theta   max over both absolute angles |theta - theta_ref|  [0, 0.5] s

Initial state (``double_pendulum initialState``, runs of scripts/initialStateRuns):
    atRest theta2     theta2 of runs/atRest-<integrator> (from a hand-written
                      state file with qDdot 0: a fresh start), [0, 1] s
    atRest same       max |row difference| of its joints.dat and that of
                      runs/<integrator> (no state file): the same run
    stale theta2      theta2 of runs/atRestStale (the file's qDdot kept): the
                      first-order error a fresh start removes, must be large
    restart           max relative difference of q, qDot, qDdot at 1 s of
                      runs/freeRestart (restarted at 0.375 s) and of
                      runs/freeStraight (deltaT 2^-13 s: the same times)
"""

import argparse
import os
import sys

import numpy as np
from scipy.interpolate import CubicHermiteSpline, CubicSpline

from flapfoam.errors import run_tool
from flapfoam.io import run_series

CASE = "."                  # the case folder: where it is run, or -case

INTEGRATORS = ("Newmark", "symplectic", "CrankNicolson")

# Acceptance limits (name -> limit); the only place they are set
TOL = {
    "theta1": 1e-8,         # rad: the prescribed joint is imposed exactly
    "theta2": 1e-3,         # rad, t in [0, 1] s
    "tau1": 1e-2,           # relative to max |tau1_ref|, t in [0, 1] s
    "energy": 5e-3,         # relative to max |W|, t in [0, 2] s
    "freeEnergy": 1e-4,     # relative to E(0), t in [0, 2] s
    "freeTheta": 1e-3,      # rad, t in [0, 0.5] s
    # self-checks of the reference and of this script's quadrature
    "refEnergyBalance": 1e-9,   # max |E - E0 - W| / max |W|
    "refFreeEnergy": 1e-10,     # max |E - E0| / E0
    "quadrature": 1e-4,         # Simpson on the rows vs the reference's W
}

WINDOW = {"theta2": 1.0, "tau1": 1.0, "freeTheta": 0.5}

# Initial state checks: limits
TOL_INITIAL = {
    "atRestTheta2": 2e-6,   # rad: as without a state file (<= 1.6e-6)
    "atRestSame": 1e-12,    # the run without a state file
    "staleTheta2": 1e-3,    # rad, a LOWER bound: the stale error is 6.7e-3
    "restart": 1e-12,       # relative to the straight run
}


# ---------------------------------------------------------------------------
# Reading

def _header_and_data(path):
    """Column names from the last '#' line that names the columns, and the
    data as a 2-D array; plus the '# parameters' entries if present."""
    names = None
    params = {}
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            words = line[1:].split()
            if words and words[0] == "parameters":
                for key, val in zip(words[1::2], words[2::2]):
                    try:
                        params[key] = float(val)
                    except ValueError:
                        params[key] = val
            elif words and words[0] == "time":
                names = words
    if names is None:
        raise ValueError(f"{path}: no '# time ...' header line")
    data = np.loadtxt(path, comments="#", ndmin=2)
    if data.shape[1] != len(names):
        raise ValueError(
            f"{path}: {data.shape[1]} columns but the header names "
            f"{len(names)}")
    cols = {n: data[:, i] for i, n in enumerate(names)}
    return cols, params


def read_reference(name, case=CASE):
    """reference/<name>.dat: (columns, parameters)"""
    return _header_and_data(os.path.join(case, "reference", name + ".dat"))


def joints(run, case=CASE):
    """The series of runs/<run> (its joints.dat: rigidBodySimulate)"""
    return run_series.read(os.path.join(case, "runs", run))


def read_eaba(run, case=CASE):
    """joints.dat of runs/<run> as absolute angles (dict of arrays)"""
    s = joints(run, case)
    q, q_dot = s.q, s.q_dot
    out = {
        "time": s.time,
        "theta1": q[:, 0],
        "theta2": q[:, 0] + q[:, 1],
        "theta1Dot": q_dot[:, 0],
        "theta2Dot": q_dot[:, 0] + q_dot[:, 1],
    }
    if 0 in s.prescribed:
        out["tau1"] = s.tau[:, s.prescribed.index(0)]
        out["power1"] = s.power[:, s.prescribed.index(0)]
    return out


# ---------------------------------------------------------------------------
# Physics of the point-mass double pendulum (same as the reference's header)

def energy(p, th1, th2, th1d, th2d):
    """T + V with V = 0 at rest hanging down"""
    l1, l2, m1, m2, g = p["l1"], p["l2"], p["m1"], p["m2"], p["g"]
    T = (0.5*(m1 + m2)*l1**2*th1d**2 + 0.5*m2*l2**2*th2d**2
         + m2*l1*l2*np.cos(th1 - th2)*th1d*th2d)
    V = (m1 + m2)*g*l1*(1 - np.cos(th1)) + m2*g*l2*(1 - np.cos(th2))
    return T + V


def simpson_cumulative(t, f):
    """Cumulative integral of f(t) at rows 0, 2, 4, ... (Simpson's rule on
    each pair of intervals, for non-uniform spacing).  Returns (idx, F)."""
    n = (len(t) - 1)//2
    h0 = t[1:2*n:2] - t[0:2*n-1:2]
    h1 = t[2:2*n+1:2] - t[1:2*n:2]
    f0, f1, f2 = f[0:2*n-1:2], f[1:2*n:2], f[2:2*n+1:2]
    s = (h0 + h1)/6*((2 - h1/h0)*f0 + (h0 + h1)**2/(h0*h1)*f1
                     + (2 - h0/h1)*f2)
    return np.arange(0, 2*n + 1, 2), np.concatenate(([0.0], np.cumsum(s)))


def on_times(ref, t, name):
    """Reference column `name` at times t: cubic Hermite for the angles
    (using their rates), cubic spline otherwise.  At the reference's own
    output times this returns its values."""
    rate = {"theta1": "theta1Dot", "theta2": "theta2Dot"}.get(name)
    if rate is not None:
        return CubicHermiteSpline(ref["time"], ref[name], ref[rate])(t)
    return CubicSpline(ref["time"], ref[name])(t)


def _maxabs(x):
    return float(np.max(np.abs(x))) if len(x) else float("nan")


# ---------------------------------------------------------------------------
# Metrics

def prescribed_metrics(run, case=CASE):
    """Errors of runs/<run> against reference/prescribed.dat"""
    ref, p = read_reference("prescribed", case)
    e = read_eaba(run, case)
    t = e["time"]
    if t[-1] < ref["time"][-1] - 1e-9:
        raise ValueError(f"{run}: joints.dat ends at t = {t[-1]}")
    w2 = t <= WINDOW["theta2"] + 1e-9
    wt = t <= WINDOW["tau1"] + 1e-9
    rwt = ref["time"] <= WINDOW["tau1"] + 1e-9

    E = energy(p, e["theta1"], e["theta2"], e["theta1Dot"], e["theta2Dot"])
    idx, W = simpson_cumulative(t, e["tau1"]*e["theta1Dot"])
    balance = E[idx] - E[0] - W

    return {
        "theta1": _maxabs(e["theta1"] - on_times(ref, t, "theta1")),
        "theta2": _maxabs(e["theta2"][w2] - on_times(ref, t[w2], "theta2")),
        "theta2_2s": _maxabs(e["theta2"] - on_times(ref, t, "theta2")),
        "tau1": _maxabs(e["tau1"][wt] - on_times(ref, t[wt], "tau1"))
                / _maxabs(ref["tau1"][rwt]),
        "energy": _maxabs(balance)/_maxabs(W),
        "power": _maxabs(e["power1"] - e["tau1"]*e["theta1Dot"]),
        "maxW": _maxabs(W),
    }


def free_metrics(case=CASE):
    """Energy drift and trajectory error of runs/free"""
    ref, p = read_reference("free", case)
    e = read_eaba("free", case)
    t = e["time"]
    if t[-1] < ref["time"][-1] - 1e-9:
        raise ValueError(f"free: joints.dat ends at t = {t[-1]}")
    E = energy(p, e["theta1"], e["theta2"], e["theta1Dot"], e["theta2Dot"])
    w = t <= WINDOW["freeTheta"] + 1e-9
    return {
        "freeEnergy": _maxabs(E - E[0])/E[0],
        "freeTheta": max(
            _maxabs(e[k][w] - on_times(ref, t[w], k))
            for k in ("theta1", "theta2")),
        "freeTheta_2s": max(
            _maxabs(e[k] - on_times(ref, t, k))
            for k in ("theta1", "theta2")),
    }


def reference_metrics(case=CASE):
    """Self-checks of the reference: energy balance, energy conservation,
    and the accuracy of simpson_cumulative on the reference's own rows"""
    pr, p = read_reference("prescribed", case)
    fr, pf = read_reference("free", case)
    Ep = energy(p, pr["theta1"], pr["theta2"], pr["theta1Dot"],
                pr["theta2Dot"])
    Ef = energy(pf, fr["theta1"], fr["theta2"], fr["theta1Dot"],
                fr["theta2Dot"])
    idx, W = simpson_cumulative(pr["time"], pr["tau1"]*pr["theta1Dot"])
    return {
        "refEnergyBalance": _maxabs(pr["E"] - pr["E"][0] - pr["W"])
                            / _maxabs(pr["W"]),
        "refEnergyColumn": max(_maxabs(Ep - pr["E"]), _maxabs(Ef - fr["E"])),
        "refFreeEnergy": _maxabs(fr["E"] - fr["E"][0])/fr["E"][0],
        "quadrature": _maxabs(W - pr["W"][idx])/_maxabs(pr["W"]),
    }


# ---------------------------------------------------------------------------
# Checks

def _line(ok, name, value, tol):
    if ok:
        return f"PASS {name} {value:.3e} < {tol:.1e}"
    return f"FAIL {name} {value:.3e} (limit {tol:.1e})"


def run_checks(case=CASE):
    """Print one PASS/FAIL line per check; return the number of failures"""
    lines = []

    def check(name, value, tol):
        lines.append((value < tol, _line(value < tol, name, value, tol)))
        print(lines[-1][1], flush=True)

    def missing(name, err):
        lines.append((False, f"FAIL {name} {err}"))
        print(lines[-1][1], flush=True)

    try:
        r = reference_metrics(case)
        check("reference_energyBalance", r["refEnergyBalance"],
              TOL["refEnergyBalance"])
        check("reference_freeEnergy", r["refFreeEnergy"],
              TOL["refFreeEnergy"])
        check("reference_energyColumn", r["refEnergyColumn"], 1e-12)
        check("compare_workQuadrature", r["quadrature"], TOL["quadrature"])
    except (OSError, ValueError) as err:
        missing("reference", err)

    for integrator in INTEGRATORS:
        try:
            m = prescribed_metrics(integrator, case)
        except (OSError, ValueError) as err:
            missing(f"{integrator}", err)
            continue
        for key in ("theta1", "theta2", "tau1", "energy"):
            check(f"{integrator}_{key}", m[key], TOL[key])
        check(f"{integrator}_power", m["power"], 1e-9)

    try:
        m = free_metrics(case)
        check("free_symplectic_energy", m["freeEnergy"], TOL["freeEnergy"])
        check("free_symplectic_theta", m["freeTheta"], TOL["freeTheta"])
    except (OSError, ValueError) as err:
        missing("free_symplectic", err)

    return sum(1 for ok, _ in lines if not ok)


def read_state(path):
    """q, qDot, qDdot of a rigidBodyMotionState file (dict of arrays)"""
    out = {}
    with open(path) as f:
        for line in f:
            words = line.replace("(", " ( ").replace(")", " ) ").split()
            if words and words[0] in ("q", "qDot", "qDdot") and "(" in words:
                i = words.index("(")
                out[words[0]] = np.array(
                    [float(w) for w in words[i + 1:words.index(")")]])
    return out


def initial_state_checks(case=CASE):
    """Print one PASS/FAIL line per initial-state check; return the number
    of failures"""
    n_fail = 0

    def check(name, ok, value, tol):
        nonlocal n_fail
        n_fail += not ok
        print(_line(ok, name, value, tol), flush=True)

    try:
        for integrator in INTEGRATORS:
            run = "atRest-" + integrator
            m = prescribed_metrics(run, case)
            check(f"{run}_theta2", m["theta2"] < TOL_INITIAL["atRestTheta2"],
                  m["theta2"], TOL_INITIAL["atRestTheta2"])
            a = joints(run, case).joints_table()[1]
            b = joints(integrator, case).joints_table()[1]
            d = _maxabs(a - b) if a.shape == b.shape else float("inf")
            check(f"{run}_sameAsNoStateFile", d <= TOL_INITIAL["atRestSame"],
                  d, TOL_INITIAL["atRestSame"])

        m = prescribed_metrics("atRestStale", case)
        ok = m["theta2"] > TOL_INITIAL["staleTheta2"]
        print(f"{'PASS' if ok else 'FAIL'} atRestStale_theta2 (qDdot kept:"
              f" the first-order error) {m['theta2']:.3e} > "
              f"{TOL_INITIAL['staleTheta2']:.1e}", flush=True)
        n_fail += not ok

        folder = "1/uniform/rigidBodyMotionState"
        straight = read_state(os.path.join(
            case, "runs", "freeStraight", folder))
        restarted = read_state(os.path.join(
            case, "runs", "freeRestart", folder))
        for key in ("q", "qDot", "qDdot"):
            d = _maxabs(restarted[key] - straight[key]) \
                / max(_maxabs(straight[key]), 1e-300)
            check(f"freeRestart_{key}_equalsStraightRun",
                  d <= TOL_INITIAL["restart"], d, TOL_INITIAL["restart"])
    except (OSError, ValueError, KeyError) as err:
        print(f"FAIL initialState {err!r}", flush=True)
        n_fail += 1

    return n_fail


def table(case=CASE):
    """Markdown table of the measured errors (for the README)"""
    print("| run | theta1 [rad] | theta2, 0-1 s [rad] | theta2, 0-2 s [rad]"
          " | tau1, 0-1 s (rel.) | energy balance (rel.) |")
    print("|---|---|---|---|---|---|")
    for integrator in INTEGRATORS:
        m = prescribed_metrics(integrator, case)
        print(f"| {integrator} | {m['theta1']:.1e} | {m['theta2']:.2e} | "
              f"{m['theta2_2s']:.2e} | {m['tau1']:.2e} | {m['energy']:.2e} |")
    print()
    m = free_metrics(case)
    print("| run | energy drift, 0-2 s (rel.) | theta, 0-0.5 s [rad] |"
          " theta, 0-2 s [rad] |")
    print("|---|---|---|---|")
    print(f"| free, symplectic | {m['freeEnergy']:.2e} | "
          f"{m['freeTheta']:.2e} | {m['freeTheta_2s']:.2e} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("action", choices=("check", "initialState", "table"))
    parser.add_argument("-case", default=CASE, help="case directory")
    args = parser.parse_args()
    if args.action == "check":
        sys.exit(1 if run_checks(args.case) else 0)
    if args.action == "initialState":
        sys.exit(1 if initial_state_checks(args.case) else 0)
    table(args.case)


if __name__ == "__main__":
    run_tool(main)
