# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Read and check the flight data (HDF5) of a drone run.

A run's file is postProcessing/flightData/<start>/flightData.h5 (the
flightData function object, src/flightData): the earliest start folder that
holds one (restarts append to it).

    flapfoam flight_data check CASE [-rows N]
        [-attr KEY=VALUE ...] [-log LOG] [-uniformStep] [-zero D:i,j]
        [-moving D:i]
        one file; every dataset has the same rows; time strictly increasing
        (-uniformStep: with a uniform step, for fixed-step runs; a
        production run's step is adaptive); no
        NaN but in the first row's loads and timers (the initial state);
        the root attributes case, level, stencil, nRanks, decomposition,
        commit present (and equal to KEY=VALUE); with -rows exactly N rows;
        with -log, a solver log of a run that was killed: every step the
        log shows completed (a later "Time =" line) has its row; with
        -zero DATASET:i,j columns i, j exactly 0 in every row, with
        -moving DATASET:i column i not 0 in the last row.
    flapfoam flight_data compare REF CASE [-tol T]
        [-timeTol S] [-datasets a,b] [-exclude timers]
        the same datasets and rows, time equal (to S seconds: a restart
        starts from the written time, a straight run sums its steps; default
        0: identical), every other dataset
        max |a - b| / max(max |REF column|, 1e-9 max |REF dataset|) <= T
        per column (timers excluded by default); one line per dataset.

One PASS/FAIL line per check; exit status 1 on a failure.  As a module:
find(case), load(case) -> (attrs, {name: array}), opened(path) -> an open
h5py.File; a run's time series as one dataclass: flapfoam.io.run_series.

A run writes its file without HDF5's file locks and closes it between
steps, so it can be read while the run goes on; a read that catches the
file before its first row or in the middle of a row (h5py raises KeyError
or OSError) is tried again every 20 ms for up to WAIT seconds while the
file is being written (changed in the last WAIT seconds), then the last
error is raised.
"""

import argparse
import glob
import os
import re
import sys
import time
from dataclasses import dataclass, field

import numpy as np

from flapfoam.harness.checklist import report
from flapfoam.io.tables import time_value
from flapfoam.errors import run_tool

WAIT = 5.0


def find(case):
    """The run's flightData.h5 (earliest start folder holding one)."""
    files = glob.glob(os.path.join(case, "postProcessing", "flightData", "*",
                                   "flightData.h5"))

    files.sort(key=lambda f: time_value(os.path.basename(os.path.dirname(f)),
                                       float("inf")))
    return files[0] if files else None


def retried(read, path):
    """read() again while it raises KeyError or OSError and path is being
    written (a row of a running run), for up to WAIT seconds; then the
    last error."""
    deadline = time.monotonic() + WAIT
    while True:
        try:
            return read()
        except (KeyError, OSError):
            written = os.path.exists(path) and \
                time.time() - os.path.getmtime(path) < WAIT
            if not written or time.monotonic() > deadline:
                raise
            time.sleep(0.02)


def opened(path):
    """path opened by h5py (its default shared lock) once its time dataset
    can be read: a reader that holds the file during the run."""
    import h5py

    def open_whole():
        f = h5py.File(path, "r")
        try:
            f["time"].shape
        except BaseException:
            f.close()
            raise
        return f
    return retried(open_whole, path)


def load(case, with_columns=False):
    """(attributes, {dataset path: array}) of a run's file: the rows time
    has (a run writes time last in a row: a dataset's row beyond them is
    one being written, or one a killed run left half written); with_columns
    also {dataset path: its column names} (the datasets' columns
    attribute)."""
    import h5py
    path = find(case)
    if path is None:
        raise FileNotFoundError("no postProcessing/flightData/*/flightData.h5"
                                " in %s" % case)

    def read():
        data, columns = {}, {}
        with h5py.File(path, "r") as f:
            attrs = {k: (v.decode() if isinstance(v, bytes) else str(v))
                     for k, v in f.attrs.items()}
            # time first: a running run appends the other datasets' row
            # before time's, so every other dataset then has at least as
            # many rows
            n = len(f["time"]) if "time" in f else None

            def visit(name, obj):
                if isinstance(obj, h5py.Dataset):
                    data[name] = obj[()]
                    if "columns" in obj.attrs:
                        columns[name] = str(obj.attrs["columns"]).split()
            f.visititems(visit)
        if n is not None:
            data["time"] = data["time"][:n]
            data = {k: v[:n] if len(v) > n else v for k, v in data.items()}
        return (attrs, data, columns) if with_columns else (attrs, data)
    return retried(read, path)


def model_label(attrs, coeffs):
    """'CFD', or for a quasi-steady run (the flight data's model attribute,
    attrs) the coefficients that flew, from the multibody coefficients
    (coeffs: its aerodynamics entries): 'QS: CL .., CD0 .., CD1 ..'."""
    if attrs.get("model") != "quasiSteady":
        return "CFD"
    wings = [e for e in coeffs.get("aerodynamics", {}).values()
             if isinstance(e, dict)]
    return "QS: " + "; ".join(", ".join(
        "%s %.4g" % (k, float(w[k][0])) for k in ("CL", "CD0", "CD1")
        if k in w) for w in wings)


@dataclass
class FileChecks:
    """What check() asserts of a run's file besides its shape and NaNs:
    the rows (None: any), the attributes' values (KEY: VALUE), a killed
    run's log whose completed steps must have rows, a uniform time step,
    datasets' columns exactly zero or moving ("DATASET:i,j" each)."""
    rows: int = None
    attrs: dict = field(default_factory=dict)
    log: str = None
    uniform_step: bool = False
    zero: list = field(default_factory=list)
    moving: list = field(default_factory=list)


@dataclass
class Tolerances:
    """compare()'s tolerances (relative per column, time in seconds) and
    datasets: the given ones (None: all but the excluded)."""
    tol: float = 0.0
    time_tol: float = 0.0
    datasets: list = None
    exclude: set = field(default_factory=lambda: {"timers"})


def _check_times(name, t, uniform_step):
    dt = np.diff(t)
    ok = len(t) > 1 and np.all(dt > 0)
    if ok and uniform_step:
        ok = np.max(np.abs(dt - dt[0])) <= 1e-9*abs(dt[0])
    return report(ok, "flightData %s: time strictly increasing%s, %g to %g"
                  % (name, " with a uniform step" if uniform_step else "",
                     t[0], t[-1]))


def _check_attrs(name, attrs, given):
    wanted = {"case": None, "level": None, "stencil": None, "nRanks": None,
              "decomposition": None, "commit": None}
    wanted.update(given)
    wrong = [k for k, v in wanted.items()
             if k not in attrs or (v is not None and attrs[k] != v)]
    return report(not wrong, "flightData %s: attributes %s%s"
                  % (name, ", ".join("%s=%s" % (k, attrs.get(k))
                                     for k in sorted(wanted)),
                     (" (wrong: %s)" % ", ".join(wrong)) if wrong else ""))


def _check_columns(name, data, spec, zero):
    """A dataset's columns ("DATASET:i,j") exactly 0 in every row (zero),
    else not 0 in the last row."""
    d, cols = spec.split(":")
    cols = [int(c) for c in cols.split(",")]
    v = np.asarray(data.get(d, np.zeros((0, 0))), dtype=float)
    if v.ndim != 2 or v.shape[1] <= max(cols):
        return report(False, "flightData %s: no columns %s of %s"
                      % (name, cols, d))
    if zero:
        worst = float(np.max(np.abs(v[:, cols])))
        return report(worst == 0.0, "flightData %s: %s columns %s exactly 0"
                      " in every row (max |value| %g)"
                      % (name, d, cols, worst))
    last = v[-1, cols]
    return report(bool(np.all(last != 0.0)), "flightData %s: %s columns %s"
                  " moving (last row %s)" % (name, d, cols, " ".join(
                      "%.3g" % x for x in last)))


def _check_log(name, t, log):
    """Steps the log started; each but the last was completed, and the
    function object wrote its row before the next "Time =" line."""
    started = [float(x) for x in re.findall(r"^Time = (\S+)$",
                                            open(log).read(), re.MULTILINE)]
    completed = started[:-1]
    missing = [x for x in completed
               if not np.any(np.abs(t - x) <= 1e-9*max(abs(x), 1e-300))]
    return report(not missing and len(completed) > 0,
                  "flightData %s: all %d steps the killed run's log "
                  "completed have their rows (file: %d rows to t = %g)%s"
                  % (name, len(completed), len(t), t[-1],
                     (" missing %s" % missing[:5]) if missing else ""))


def check(case, want):
    """The PASS/FAIL lines of a run's file (want: a FileChecks); 1 if one
    failed, else 0."""
    try:
        attrs, data = load(case)
    except (OSError, FileNotFoundError) as e:
        return report(False, "flightData %s: cannot read: %s" % (case, e))
    name = os.path.basename(os.path.normpath(case))
    t = data.get("time")
    if t is None:
        return report(False, "flightData %s: no time dataset" % name)
    n = len(t)
    rows = {k: len(v) for k, v in data.items()}
    status = report(all(r == n for r in rows.values()),
                    "flightData %s: %d datasets, all with %d rows"
                    % (name, len(rows), n))
    if want.rows is not None:
        status |= report(n == want.rows, "flightData %s: %d rows (expected"
                         " %d)" % (name, n, want.rows))
    status |= _check_times(name, t, want.uniform_step)
    bad = [k for k, v in data.items()
           if np.isnan(np.asarray(v, dtype=float)[1:]).any()]
    status |= report(not bad, "flightData %s: no NaN after the initial row%s"
                     % (name, (" (NaN in %s)" % ", ".join(bad)) if bad
                            else ""))
    status |= _check_attrs(name, attrs, want.attrs)
    for spec in want.zero:
        status |= _check_columns(name, data, spec, True)
    for spec in want.moving:
        status |= _check_columns(name, data, spec, False)
    if want.log:
        status |= _check_log(name, t, want.log)
    return status


def _relative_difference(x, y):
    """The largest |x - y| of a dataset per column over its column's
    largest |x|, floored at 1e-9 of the dataset's largest value (a column
    of round-off noise, e.g. y of a planar motion, is not compared to
    itself); NaN in both is equal, in one infinitely different."""
    x2 = x.reshape(len(x), -1)
    y2 = y.reshape(len(y), -1)
    both = np.isnan(x2) & np.isnan(y2)
    big = np.nanmax(np.abs(x2)) if x2.size else 0.0
    scale = np.maximum(np.nanmax(np.abs(x2), axis=0),
                       max(1e-9*big, 1e-300))
    diff = np.where(both, 0.0, np.abs(x2 - y2))/scale
    if np.isnan(diff).any():
        return float("inf")
    return float(np.nanmax(diff)) if diff.size else 0.0


def compare(ref_case, case, tols):
    """The PASS/FAIL lines of a run's file against a reference run's
    (tols: a Tolerances); 1 if one failed, else 0."""
    try:
        _, A = load(ref_case)
        _, B = load(case)
    except (OSError, FileNotFoundError) as e:
        return report(False, "flightData compare: cannot read: %s" % e)
    ref = os.path.basename(os.path.normpath(ref_case))
    name = os.path.basename(os.path.normpath(case))
    names = tols.datasets or sorted(set(A) - tols.exclude)
    status = report(set(A) == set(B), "flightData %s vs %s: the same %d "
                    "datasets" % (name, ref, len(A)))
    if len(A["time"]) != len(B["time"]) or \
            np.any(np.abs(A["time"] - B["time"]) > tols.time_tol):
        return report(False, "flightData %s vs %s: times differ (%d and %d "
                      "rows, tol %g s)" % (name, ref, len(A["time"]),
                                           len(B["time"]), tols.time_tol))
    status |= report(True, "flightData %s vs %s: the same %d rows, times "
                     "equal%s" % (name, ref, len(A["time"]),
                                  " to %g s" % tols.time_tol
                                  if tols.time_tol else ""))
    worst = 0.0
    lines = []
    for d in names:
        if d == "time" or d not in B:
            continue
        x = np.asarray(A[d], dtype=float)
        y = np.asarray(B[d], dtype=float)
        if x.shape != y.shape:
            status |= report(False, "flightData %s vs %s: %s shapes %s and "
                             "%s" % (name, ref, d, x.shape, y.shape))
            continue
        e = _relative_difference(x, y)
        worst = max(worst, e)
        lines.append("%s %.1e" % (d, e))
    status |= report(worst <= tols.tol, "flightData %s vs %s: max relative "
                     "difference %.2e (tol %g; per dataset: %s)"
                     % (name, ref, worst, tols.tol, ", ".join(lines)))
    return status


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="command", required=True)
    c = sub.add_parser("check")
    c.add_argument("case")
    c.add_argument("-rows", type=int)
    c.add_argument("-attr", action="append", default=[])
    c.add_argument("-log")
    c.add_argument("-uniformStep", dest="uniform_step", action="store_true",
                   help="also a uniform time step (a fixed-step run)")
    c.add_argument("-zero", action="append", default=[])
    c.add_argument("-moving", action="append", default=[])
    m = sub.add_parser("compare")
    m.add_argument("ref")
    m.add_argument("case")
    m.add_argument("-tol", type=float, default=0.0)
    m.add_argument("-timeTol", dest="time_tol", type=float, default=0.0)
    m.add_argument("-datasets")
    m.add_argument("-exclude", default="timers")
    a = ap.parse_args(argv)
    if a.command == "check":
        return check(a.case, FileChecks(
            a.rows, dict(kv.split("=", 1) for kv in a.attr), a.log,
            a.uniform_step, a.zero, a.moving))
    return compare(a.ref, a.case, Tolerances(
        a.tol, a.time_tol, a.datasets.split(",") if a.datasets else None,
        set(a.exclude.split(",")) if a.exclude else set()))


if __name__ == "__main__":
    sys.exit(run_tool(main))
