# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The checks of the Alltest scripts that read results (flight data, joints
tables, fitted entries, sweep tables), each a function returning
(ok, text) and unit-tested (scripts/tests/test_result_checks.py); the
scripts call them through

    flapfoam result_checks CHECK ARGS...

which prints "PASS text" or "FAIL text" and exits 0 or 1.  CHECK:

    flight-data-joints CASE    the flight data's time and q of every joint
                               equal rigidBodySimulate's joints.dat (15
                               digits), every value finite after row 0
    references FILE            doublePendulumReference's table (-mode
                               prescribed) = flapfoam.models.chain_reference's
    authors-controller CASE    the first controller update of a converted
                               authors' dictionary = their PD law
    qs-entry ENTRY [-log LOG] [-tol T]
                               the fitted CL, CD0, CD1 = 1.7, 0.25, 2.3 (the
                               synthetic wing's); with -log R^2 = 1
    qs-reference REF JOINTS [-tol T]
                               joints.dat's x, z = the quasiSteady reference
    finite-rows FILE N         a table of N rows, every value finite
    sweep-table CSV            bench/quasiSteady's 2 x 2 sweep: finite, more
                               stroke more climb rate and power, power > 0
    hover-table CSV            its hover: one point, flapAmplitude in
                               (1.2, 1.5), mean climb acceleration and rate
                               near 0
    control-errors RUN N       controlPlot's errors = the controller's at
                               each of its N updates (1e-12)
    control-convergence FINE COARSE
                               controlPlot's measures of a run (COARSE, 5
                               cycles) against a finer step's (FINE)
    gain-sweep-table CSV       gainSweep's 2 x 2 table: 4 rows, status ok,
                               finite metrics
    flight-data-times FILE     prints the time column of a flightData.h5
    half-row CASE              the run's flightData.h5 made to end with a
                               half-written row (every dataset but time one
                               row longer); prints the datasets changed and
                               the row counts the reader loads
    rows-summary FILE          prints "times | row counts, cells of 999"
    hold-open FILE SECONDS     holds FILE open (h5py's default lock) once
                               readable; prints the rows then
"""

import argparse
import math
import os
import re
import sys
import time

import numpy as np

from flapfoam.io import flight_data, run_series
from flapfoam.errors import run_tool

SYNTHETIC_WING = {"CL": 1.7, "CD0": 0.25, "CD1": 2.3}


def flight_data_joints(case):
    """A quasi-steady run's flight data against its joints.dat."""
    flight = run_series.read(case)
    table = run_series.read(case, tables="rigidBodySimulate")
    n = flight.q.shape[1]
    h = np.column_stack([flight.time, flight.q])
    h = np.array([[float("%.15g" % v) for v in r] for r in h])
    j = np.column_stack([table.time, table.q])
    same = h.shape == j.shape and bool((h == j).all())
    bad = [k for k, v in flight.arrays().items()
           if not np.isfinite(v[1:]).all()]
    # the free joints' order is the case's (SW, BW: z, x; two wings: x, y, z)
    return same and not bad, (
        "flight data = joints.dat: %d rows, time and q_0..q_%d exactly (15"
        " digits), final q_0..q_%d = %s; non-finite: %s"
        % (len(h), n - 1, min(n, 3) - 1,
           " ".join("%.6g" % v for v in h[-1, 1:4]), bad or "none"))


def references(path):
    """doublePendulumReference's theta2 against chain_reference's."""
    from flapfoam.studies import integrator_order
    times, angles = integrator_order.reference(
        integrator_order.SYSTEMS["doublePendulum"])
    cpp = np.loadtxt(path)
    d = float(np.max(np.abs(cpp[:, 2] - angles[:, 1])))
    ok = cpp.shape[0] == len(times) \
        and np.allclose(cpp[:, 0], times, atol=1e-12) and d < 1e-10
    return ok, "theta2 %.3g rad (limit 1e-10)" % d


def _scaled(u, lo, hi):
    """Their tanh map of u onto [lo, hi]."""
    return (math.tanh(u) + 1)/2*(hi - lo) + lo


def authors_pd_law(z, x, pitch, rates):
    """The paper authors' midStartControl_xzth_PD outputs (their
    wangParametrization.C, the gains of their dictionary) of the sphere's
    z, x, pitch and their rates (vz, vx, omega), in flapFoam's entries."""
    vz, vx, w = rates
    a_phi = -_scaled(-30*(z - 0.01) - 5*vz + 0.2, 1.2, 1.7)
    beta = -_scaled(4*x + 1*vx, -0.3, 0.3)
    theta = -math.sin(pitch)        # their E()[2]: E_xz = -sin(pitch), Ry
    off = _scaled(3*math.asin(theta) + 0.2*w, -0.2, 0.2)
    # their stroke spans -A(1 + off/|Aphi|) .. A(1 - off/|Aphi|), Aphi < 0
    return {"flapping.amplitude": -a_phi, "stroke.offset": beta,
            "flapping.offset": off}


def authors_controller(case):
    """The first controller update in CASE/log (at t = 0.05 s) against
    authors_pd_law of the state joints.dat has then."""
    log = open(case + "/log").read()
    m = re.search(r"PID controller update 1 at t = (\S+):(.*)", log)
    if not m:
        return False, "no controller update in %s/log" % case
    out = {k: float(v) for k, v in
           re.findall(r"(\w+\.\w+) = ([-0-9.e+]+)", m.group(2))}
    rows = run_series.read(case, tables="rigidBodySimulate")
    t = float(m.group(1))
    k = np.argmin(abs(rows.time - t))
    # Pz, Px, Ry of the sphere: joints 0, 1, 2
    q, q_dot = rows.q[k], rows.q_dot[k]
    want = authors_pd_law(q[0], q[1], q[2], (q_dot[0], q_dot[1], q_dot[2]))
    err = max(abs(out.get(k, math.inf) - v) for k, v in want.items())
    return err < 1e-12 and abs(t - 0.05) < 1e-9, (
        "t %.6g: %s; authors %s; max difference %.2e" % (t, out, want, err))


def entry_coefficients(text):
    """CL, CD0, CD1 of a quasiSteady entry's text."""
    return {k: float(re.search(r"\b%s\s+(\S+);" % k, text).group(1))
            for k in SYNTHETIC_WING}


def qs_entry(entry, log=None, tol=1e-6):
    """A fitted entry against the synthetic wing's coefficients; with the
    fit's log, its R^2 = 1 and the entry's type quasiSteady."""
    text = open(entry).read()
    got = entry_coefficients(text)
    err = max(abs(got[k]/v - 1) for k, v in SYNTHETIC_WING.items())
    ok = err <= tol
    summary = "CL %.8g CD0 %.8g CD1 %.8g, max relative error %.2g" \
        % (got["CL"], got["CD0"], got["CD1"], err)
    if log is not None:
        fitted = open(log).read().split("QS fitted")[1].split("\n")[0]
        r2 = [float(v) for v in re.findall(r"R\^2 (\S+),", fitted)]
        ok = ok and bool(r2) and min(r2) > 1 - 1e-12 \
            and "type        quasiSteady;" in text
        summary += ", R^2 %s" % " ".join(map(str, r2))
    return ok, summary


def qs_reference(reference, joints, tol=1e-3):
    """joints.dat's x and z against the quasiSteady reference: the
    largest difference relative to the reference's range, each."""
    from flapfoam.models.quasi_steady import errors
    err = errors(np.loadtxt(reference), np.loadtxt(joints))
    return all(e <= tol for e in err.values()), ", ".join(
        "%s: max |run - reference| = %.3g of its range" % (k, e)
        for k, e in err.items()) + " (tol %g)" % tol


def finite_rows(path, rows):
    """A table of the given number of rows, every value finite."""
    d = np.loadtxt(path, ndmin=2)
    ok = len(d) == rows and bool(np.isfinite(d).all())
    return ok, "%d rows (expected %d), %s" % (
        len(d), rows, "all finite" if np.isfinite(d).all() else "NOT finite")


def sweep_table(path):
    """bench/quasiSteady's 2 x 2 sweep: 4 finite rows; the larger flapping
    amplitude climbs faster and costs more power; power > 0."""
    d = np.genfromtxt(path, delimiter=",", names=True)
    ok = d.size == 4 and all(np.isfinite(d[n]).all() for n in d.dtype.names)
    if ok:
        up = d["flapAmplitude"] > d["flapAmplitude"].min()
        ok = bool((d["meanClimbRate"][up] > d["meanClimbRate"][~up]).all()
                  and (d["meanPower"][up] > d["meanPower"][~up]).all()
                  and (d["meanPower"] > 0).all())
    return ok, "%d rows: climb rate %s, power %s" % (
        d.size, d["meanClimbRate"], d["meanPower"])


def hover_table(path):
    """The hover stage's table: one point, inside the grid (bench/
    quasiSteady/Alltest's flapAmplitude 1.0 to 1.5), hovering."""
    d = np.genfromtxt(path, delimiter=",", names=True)
    ok = d.size == 1 and 1.0 < d["flapAmplitude"] < 1.5 \
        and abs(d["meanClimbAcceleration"]) < 1e-4 \
        and abs(d["meanClimbRate"]) < 3e-3
    return bool(ok), "flapAmplitude %s, climb acceleration %s, rate %s" % (
        d["flapAmplitude"], d["meanClimbAcceleration"], d["meanClimbRate"])


def control_errors(case, updates):
    """controlPlot measures what the controller measures: the controller
    updates at the start of the step after a cycle's end, so its error is
    that of the row before the one where its column changes."""
    from flapfoam.plots.control import Run
    r = Run(case)
    worst, n = 0.0, set()
    for s in r.terms:
        c = r.control[s.label + ".error"]
        rows = np.flatnonzero(np.diff(c) != 0) + 1
        n.add(len(rows))
        if len(rows):
            worst = max(worst, float(np.max(np.abs(
                c[rows] - r.errors[s.label][rows - 1]))))
    return worst <= 1e-12 and n == {updates}, (
        "%s: %s updates, max difference %.2e" % (
            ", ".join(s.label for s in r.terms),
            "/".join(map(str, sorted(n))), worst))


CONTROL_TOLERANCE = {"height.z": 1e-4, "surge.x": 3e-4, "pitch.theta": 3e-4}


def control_convergence(fine, coarse):
    """The measures of a run at a coarser step (5 cycles) against those of
    a finer one, each within CONTROL_TOLERANCE."""
    from flapfoam.plots.control import Run
    fine, coarse = Run(fine), Run(coarse)
    ok, text = coarse.t[-1] > 0.2499, []
    for label, m in coarse.measures.items():
        d = np.max(np.abs(m - np.interp(coarse.t, fine.t,
                                        fine.measures[label])))
        tol = CONTROL_TOLERANCE[label]
        ok = ok and d <= tol
        text.append("%s %.2g (tol %g)" % (label, d, tol))
    return bool(ok), ", ".join(text)


def gain_sweep_table(path):
    """gainSweep's 2 x 2 table: 4 rows, each ok with finite metrics."""
    import csv
    with open(path) as fh:
        rows = list(csv.DictReader(fh))
    ok = len(rows) == 4 and all(r["status"] == "ok" for r in rows) and all(
        math.isfinite(float(r[q + ".maxAbsError"])) for r in rows
        for q in CONTROL_TOLERANCE)
    return ok, "%d rows, status %s" % (
        len(rows), " ".join(r["status"] for r in rows))


def flight_data_times(path):
    """The time column of a flightData.h5, "%g" each."""
    import h5py
    with h5py.File(path, "r") as f:
        return " ".join("%g" % t for t in f["time"][:])


def half_row(case):
    """CASE's flightData.h5 made to end with a half-written row (every
    dataset but time one row longer, 999): "datasets row-counts-loaded"."""
    import h5py
    with h5py.File(flight_data.find(case), "r+") as f:
        names = []
        f.visititems(lambda n, o: names.append(n)
                     if isinstance(o, h5py.Dataset) and n != "time" else None)
        for n in names:
            d = f[n]
            d.resize(d.shape[0] + 1, axis=0)
            d[-1] = 999.0
    _, data = flight_data.load(case)
    return "%d %s" % (len(names),
                      " ".join(sorted({str(len(v)) for v in data.values()})))


def rows_summary(path):
    """"times | sorted row counts, cells holding 999" of a flightData.h5."""
    import h5py
    rows, bad = set(), [0]
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                rows.add(obj.shape[0])
                bad[0] += int(np.sum(obj[()] == 999.0))
        f.visititems(visit)
    return "%s | %s %d" % (flight_data_times(path), sorted(rows), bad[0])


def hold_open(path, seconds, wait=30.0):
    """path held open (h5py's default shared lock) for the given seconds
    once it exists and a row can be read; the rows it had then."""
    deadline = time.monotonic() + wait
    while not os.path.exists(path) \
            and time.monotonic() < deadline:
        time.sleep(0.05)
    with flight_data.opened(path) as f:
        n = f["time"].shape[0]
        time.sleep(seconds)
    return n


def parser():
    p = argparse.ArgumentParser(
        prog="flapfoam result_checks",
        description="The result checks of the Alltest scripts.")
    sub = p.add_subparsers(dest="check", required=True)
    sub.add_parser("flight-data-joints").add_argument("case")
    sub.add_parser("references").add_argument("file")
    sub.add_parser("authors-controller").add_argument("case")
    s = sub.add_parser("qs-entry")
    s.add_argument("entry")
    s.add_argument("-log")
    s.add_argument("-tol", type=float, default=1e-6)
    s = sub.add_parser("qs-reference")
    s.add_argument("reference")
    s.add_argument("joints")
    s.add_argument("-tol", type=float, default=1e-3)
    s = sub.add_parser("finite-rows")
    s.add_argument("file")
    s.add_argument("rows", type=int)
    sub.add_parser("sweep-table").add_argument("file")
    sub.add_parser("hover-table").add_argument("file")
    s = sub.add_parser("control-errors")
    s.add_argument("case")
    s.add_argument("updates", type=int)
    s = sub.add_parser("control-convergence")
    s.add_argument("fine")
    s.add_argument("coarse")
    sub.add_parser("gain-sweep-table").add_argument("file")
    sub.add_parser("flight-data-times").add_argument("file")
    sub.add_parser("half-row").add_argument("case")
    sub.add_parser("rows-summary").add_argument("file")
    s = sub.add_parser("hold-open")
    s.add_argument("file")
    s.add_argument("seconds", type=float)
    return p


CHECKS = {
    "flight-data-joints": lambda a: flight_data_joints(a.case),
    "references": lambda a: references(a.file),
    "authors-controller": lambda a: authors_controller(a.case),
    "qs-entry": lambda a: qs_entry(a.entry, a.log, a.tol),
    "qs-reference": lambda a: qs_reference(a.reference, a.joints, a.tol),
    "finite-rows": lambda a: finite_rows(a.file, a.rows),
    "sweep-table": lambda a: sweep_table(a.file),
    "hover-table": lambda a: hover_table(a.file),
    "control-errors": lambda a: control_errors(a.case, a.updates),
    "control-convergence": lambda a: control_convergence(a.fine, a.coarse),
    "gain-sweep-table": lambda a: gain_sweep_table(a.file),
}
PRINTS = {
    "flight-data-times": lambda a: flight_data_times(a.file),
    "half-row": lambda a: half_row(a.case),
    "rows-summary": lambda a: rows_summary(a.file),
    "hold-open": lambda a: hold_open(a.file, a.seconds),
}


def main(argv=None):
    a = parser().parse_args(argv)
    if a.check in PRINTS:
        print(PRINTS[a.check](a))
        return 0
    ok, text = CHECKS[a.check](a)
    print("%s %s" % ("PASS" if ok else "FAIL", text))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(run_tool(main))
