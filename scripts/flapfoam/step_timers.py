# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The step timers of a run (stepTimers.dat of the stepTimers function object):
the files of a case or folder, their rows, joined over restarts, and the
summary (mean and median per step of every column, closure of rbd + overset
+ pimple against total).  numpy only (the chart: plotStepTimers).
"""

import os
import sys

import numpy as np

from flapfoam.tables import time_value

GROUPS = ["rbd", "overset", "pimple", "total"]


def is_count(name):
    """Whether a column counts (timedOversetFvMesh: the iterations of each
    pressure solve, pIterations<k>, and pimpleInterpolations) instead of
    holding seconds."""
    return name.startswith("pIterations") or name == "pimpleInterpolations"


# The pimple column split (timedOversetFvMesh's solves and interpolations,
# the fvOption pimpleTimers' laps): group -> its parts
PIMPLE_SPLIT = (
    ("momentum", ("pimpleMomentum", "pimpleMomentumSolve")),
    ("pressure", ("pimplePressure", "pimplePressureSolve")),
    ("pressureSolve", ("pimplePressureSolve",)),
    ("turbulence", ("pimpleTurbulence", "pimpleOtherSolve")),
    ("interpolate", ("pimpleOversetInterpolate",)),
)


def pimple_split(values):
    """The pimple column's groups (seconds) of a row or of per-column means
    or medians, 'rest' (pimple less momentum, pressure, turbulence and
    interpolate), the pressure iterations of the step (the pIterations<k>
    summed) and the interpolation calls; None without the laps (runs
    without the fvOption pimpleTimers)."""
    if "pimpleTurbulence" not in values:
        return None
    out = {g: sum(values.get(p, 0.0) for p in parts)
           for g, parts in PIMPLE_SPLIT}
    out["rest"] = values["pimple"] - sum(
        out[g] for g in ("momentum", "pressure", "turbulence", "interpolate"))
    out["pIterations"] = sum(v for k, v in values.items()
                             if k.startswith("pIterations"))
    out["interpolations"] = values.get("pimpleInterpolations", 0.0)
    return out


def find_files(path):
    """The stepTimers.dat files of an input, in start-time order."""
    if os.path.isfile(path):
        return [path]
    found = []
    for root, _dirs, files in os.walk(path):
        for name in files:
            if name.startswith("stepTimers") and name.endswith(".dat") \
                    and "Summary" not in name and "Ranks" not in name:
                found.append(os.path.join(root, name))
    if not found:
        sys.exit("plotStepTimers: no stepTimers.dat under " + path)

    return sorted(found, key=lambda f: (
        time_value(os.path.basename(os.path.dirname(f)), 0.0), f))


def read_file(fname):
    """Rows of one file as a list of dicts {column: value}; a header line
    ('# time ...') sets the columns of the rows below it."""
    columns = None
    rows = []
    with open(fname) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "#":
                if len(words) > 1 and words[1] == "time":
                    columns = words[1:]
                continue
            if columns is None:
                sys.exit("plotStepTimers: %s: data before the '# time' "
                         "header" % fname)
            values = [float(w) for w in words]
            if len(values) != len(columns):
                sys.exit("plotStepTimers: %s: a row of %d values under a "
                         "header of %d columns" %
                         (fname, len(values), len(columns)))
            rows.append(dict(zip(columns, values)))
    return rows


def read_ranks(fname):
    """The rows of stepTimersRanks.dat (per rank its own mean per step of
    every column) as dicts {column: value}; [] if there is none."""
    if not os.path.isfile(fname):
        return []
    columns, rows = None, []
    with open(fname) as f:
        for line in f:
            words = line.split()
            if words[:2] == ["#", "rank"]:
                columns = words[1:]
            elif words and words[0] != "#" and columns:
                rows.append(dict(zip(columns, map(float, words))))
    return rows


def read_input(path, n_startup):
    """Columns (in order of appearance) and a 2-D array of the steps after
    the start-up rows of each file; restarts replace the overlapping
    times of the earlier run."""
    columns = []
    rows = []
    for fname in find_files(path):
        file_rows = read_file(fname)[n_startup:]
        if file_rows:
            t0 = file_rows[0]["time"]
            rows = [r for r in rows if r["time"] < t0]
        rows.extend(file_rows)
        for r in file_rows:
            for c in r:
                if c not in columns:
                    columns.append(c)
    # A part missing in a row did not run in that step: zero
    data = np.array([[r.get(c, 0.0) for c in columns] for r in rows])
    return columns, data


def summary(label, columns, data):
    """Print the numbers; return the mean per step of each column."""
    col = {c: data[:, i] for i, c in enumerate(columns)}
    total = col["total"]
    parts = col["rbd"] + col["overset"] + col["pimple"]
    closure = np.abs(parts - total)/np.where(total > 0, total, 1)
    col_other = total - parts
    mean_total = total.mean()

    print("%s: %d steps, time %g to %g" %
          (label, len(total), col["time"][0], col["time"][-1]))
    print("    %-26s %14s %14s %8s" % ("part", "mean [s]", "median [s]",
                                       "share"))
    names = [c for c in columns if c != "time"]
    names.insert(names.index("total") + 1, "other")
    means = {}
    for name in names:
        v = col_other if name == "other" else col[name]
        means[name] = v.mean()
        share = "-" if is_count(name) else \
            "%7.2f%%" % (100*v.mean()/mean_total)
        print("    %-26s %14.6g %14.6g %8s" %
              (name, v.mean(), np.median(v), share))
    print("    closure |rbd + overset + pimple - total|/total: "
          "max %.2f%%, mean %.2f%% (step at time %g)" %
          (100*closure.max(), 100*closure.mean(),
           col["time"][np.argmax(closure)]))
    return means

