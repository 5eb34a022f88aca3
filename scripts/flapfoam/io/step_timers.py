# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The step timers of a run (stepTimers.dat of the stepTimers function object):
the files of a case or folder, their rows, joined over restarts, and the
summary (mean and median per step of every column, closure of rbd + overset
+ pimple against total).  numpy only (the chart: plotStepTimers).
"""

import os

import numpy as np

from flapfoam.io.tables import time_value
from flapfoam.errors import FlapFoamError

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
        raise FlapFoamError("stepTimers: no stepTimers.dat under " + path)

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
                raise FlapFoamError("stepTimers: %s: data before the '# time' "
                                    "header" % fname)
            values = [float(w) for w in words]
            if len(values) != len(columns):
                raise FlapFoamError("stepTimers: %s: a row of %d values under a "
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


# The parts of a step as a tree: (label, columns summed, children); a node
# whose columns a run lacks (or are all zero: no flow in a quasi-steady
# run) is left out; "rest" rows are the parent less its children (of the
# step: "other", the function objects and writes, preUpdate among them)
STENCIL_PARTS = ("Transform", "Voxels", "Holes", "Donors", "Flood",
                 "Weights")
TREE = ("step (total)", ("total",), (
    ("rbd", ("rbd",), ()),
    ("overset", ("overset",), (
        ("move points", ("oversetMovePoints", "oversetStencil")
         + tuple("oversetStencil" + p for p in STENCIL_PARTS), (
            ("stencil update", ("oversetStencil",)
             + tuple("oversetStencil" + p for p in STENCIL_PARTS),
             tuple((p.lower(), ("oversetStencil" + p,), ())
                   for p in STENCIL_PARTS)),)),
        ("addressing", ("oversetAddressing",), ()),
        ("interpolate", ("oversetInterpolate",), ()))),
    ("pimple", ("pimple",), (
        ("momentum", ("pimpleMomentum", "pimpleMomentumSolve"), (
            ("solve", ("pimpleMomentumSolve",), ()),)),
        ("pressure", ("pimplePressure", "pimplePressureSolve"), (
            ("solve", ("pimplePressureSolve",), ()),)),
        ("turbulence", ("pimpleTurbulence", "pimpleOtherSolve"), ()),
        ("overset interpolation", ("pimpleOversetInterpolate",), ()),
        ("wait for the slowest rank", ("pimpleSync",), ())))))


def tree_rows(col, node=TREE, depth=0):
    """(depth, label, per-step values) of the tree's nodes that the
    columns col hold (not all zero), each parent's rest after its
    children."""
    label, names, children = node
    if not any(n in col for n in names):
        return []
    v = sum(col[n] for n in names if n in col)
    if depth > 0 and not np.any(v):
        return []
    rows = [(depth, label, v)]
    kids = [r for c in children for r in tree_rows(col, c, depth + 1)]
    if kids:
        rows += kids
        rest = v - sum(r[2] for r in kids if r[0] == depth + 1)
        rows.append((depth + 1, "other (function objects, writes)"
                     if depth == 0 else "rest", rest))
    return rows


def slowest_rank_tree(label, ranks):
    """Print, for a parallel run, the tree of the slowest rank's own means
    (ranks: the rows of stepTimersRanks.dat): the columns of stepTimers.dat
    are maxima over the ranks, taken from different ranks, so their parts
    need not add up to their parent; one rank's do."""
    if len(ranks) < 2:
        return
    row = max(ranks, key=lambda r: r.get("total", 0))
    col = {c: np.array([v]) for c, v in row.items()}
    print("%s, rank %d of %d (the slowest; its own means: its parts add up,"
          " which the maxima above need not)" % (label, int(row["rank"]),
                                                 len(ranks)))
    for depth, name, v in tree_rows(col):
        print("    %-36s %12.4g %21s %7.2f%%" % (
            "  "*depth + name, v[0], "",
            100*v[0]/row["total"] if row["total"] > 0 else 0))


def summary(label, columns, data, n_startup=None):
    """Print the parts of a step as a tree (mean and median per step, the
    share of the step; each part inside its parent, the shares of a
    parent's rows adding up to its own), the counts apart and the closure;
    return the mean per step of each column."""
    col = {c: data[:, i] for i, c in enumerate(columns)}
    total = col["total"]
    parts = sum(col[g] for g in ("rbd", "overset", "pimple") if g in col)
    closure = np.abs(parts - total)/np.where(total > 0, total, 1)
    mean_total = total.mean()

    print("%s: %d steps, time %g to %g%s" % (
        label, len(total), col["time"][0], col["time"][-1],
        "" if n_startup is None else " (the first %d step(s) of each start"
        " left out: start-up)" % n_startup))
    print("    %-36s %12s %12s %8s" % ("part [s per step]", "mean",
                                       "median", "share"))
    # a run without flow (the quasi-steady model): no overset or pimple
    # rows (their bare columns only time the calls), no closure
    flow = "oversetMovePoints" in col or "pimpleMomentum" in col
    if not flow:
        col = {c: v for c, v in col.items() if c not in ("overset", "pimple")}
    for depth, name, v in tree_rows(col):
        print("    %-36s %12.4g %12.4g %7.2f%%" % (
            "  "*depth + name, v.mean(), np.median(v),
            100*v.mean()/mean_total if mean_total > 0 else 0))
    counts = [c for c in columns if is_count(c)]
    if counts:
        print("    counts per step (mean): " + ", ".join(
            "%s %.4g" % (c, col[c].mean()) for c in counts))
    if flow:
        print("    closure |rbd + overset + pimple - total|/total: max"
              " %.2f%%, mean %.2f%% (step at time %g)" % (
                  100*closure.max(), 100*closure.mean(),
                  col["time"][np.argmax(closure)]))
    means = {c: data[:, i].mean() for i, c in enumerate(columns)
             if c != "time"}
    means["other"] = (total - parts).mean()
    return means

