# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The scaling model (flapfoam.scalingModel) against timed runs: read the
archives of bench/scaling/measured (scaling-16core-<level>.tar.gz, or a
folder with runs.tsv, pingPong.log and runs/<stencil>-<method>-np<N>/),
calibrate the model's constants on some of the runs, compare its step
with every run's, and the causes of one partition's PIMPLE against
another's (flapfoam.scalingCauses).  numpy; scipy for calibrate.

A run's measured step: rbd + overset + pimple of the step timers (max
over ranks), the median over the steps after the start-up ones (runs.tsv);
its pressure iterations: the PBiCGStab solves of p per step in its log,
the mean over the same steps; its ranks: the solver's oversetRankReport.
The model's inputs: that report, the level's serial run of the same
stencil (cCell, cWork, rbd, serial iterations) and the ping-pong.
"""

import dataclasses
import fnmatch
import glob
import math
import os
import re
import tarfile
import tempfile

import numpy as np

from flapfoam import rankTables, scalingModel, stepTimers

STENCILS = {"octree": scalingModel.OCTREE, "ID": scalingModel.STOCK}
PARTS = ("rbd", "overset", "pimple", "pimpleOversetInterpolate",
         "oversetStencilVoxels")


@dataclasses.dataclass
class Run:
    """One timed run: level, stencil (short: octree, ID), method, ranks,
    measured (medians of PARTS and "step"), iterations (pressure, per
    step), decomposition (scalingModel.Decomposition) and machine
    (alpha, beta)."""
    level: str
    stencil: str
    method: str
    ranks: int
    measured: dict
    iterations: float
    decomposition: scalingModel.Decomposition
    machine: tuple

    @property
    def name(self):
        return "%s/%s-%s-np%d" % (self.level, self.stencil, self.method,
                                  self.ranks)


def archive_root(path, scratch):
    """The folder of an archive (a .tar.gz, unpacked under SCRATCH, or a
    folder) that holds runs.tsv."""
    if os.path.isfile(path):
        out = os.path.join(scratch, os.path.basename(path).split(".")[0])
        with tarfile.open(path) as tar:
            if hasattr(tarfile, "data_filter"):
                tar.extractall(out, filter="data")
            else:
                tar.extractall(out)
        path = out
    found = sorted(glob.glob(os.path.join(path, "**", "runs.tsv"),
                             recursive=True), key=len)
    if not found:
        raise ValueError("%s: no runs.tsv" % path)
    return os.path.dirname(found[0])


def read_level(root):
    """The level named in summary.txt ("level coarse, ..."), else the
    folder's name after its last '-'."""
    fname = os.path.join(root, "summary.txt")
    if os.path.isfile(fname):
        with open(fname) as f:
            m = re.search(r"^level (\w+)", f.read(), re.M)
        if m:
            return m.group(1)
    return os.path.basename(os.path.abspath(root)).split("-")[-1]


def read_ping_pong(fname):
    """(alpha, beta) of a pingPong log's last 'alpha A beta B' line."""
    found = None
    with open(fname) as f:
        for line in f:
            m = re.search(r"alpha (\S+) beta (\S+)", line)
            if m:
                found = (float(m.group(1)), float(m.group(2)))
    if found is None:
        raise ValueError("%s: no 'alpha A beta B' line" % fname)
    return found


def pressure_iterations(log, startup):
    """Mean over the steps after STARTUP of the p solves' iterations per
    step."""
    with open(log, errors="replace") as f:
        steps = f.read().split("\nTime = ")[1:]
    counts = [sum(int(n) for n in re.findall(
        r"Solving for p,.*No Iterations (\d+)", s)) for s in steps]
    return float(np.mean(counts[startup:]))


def read_medians(folder, startup):
    """Medians over the timed steps of PARTS and of the step (rbd +
    overset + pimple per step)."""
    columns, data = stepTimers.read_input(folder, startup)
    col = {c: data[:, i] for i, c in enumerate(columns)}
    zero = np.zeros(len(data))
    out = {p: float(np.median(col.get(p, zero))) for p in PARTS}
    out["step"] = float(np.median(col["rbd"] + col["overset"]
                                  + col["pimple"]))
    return out


RUN_NAME = re.compile(r"^(\w+)-(\w+)-np(\d+)(-renumbered)?(?:-r(\d+))?$")


def read_rows(root):
    """runs.tsv's rows (dicts) of the runs that ended, with their folder,
    grouped by (stencil, method, ranks, renumbered): the rounds of a
    configuration (runTimed -repeat: names ending -r<R>) together."""
    with open(os.path.join(root, "runs.tsv")) as f:
        header = f.readline().rstrip("\n").split("\t")
        rows = [dict(zip(header, line.rstrip("\n").split("\t")))
                for line in f if line.strip()]
    groups = {}
    for row in rows:
        folder = os.path.join(root, "runs", row["name"])
        m = RUN_NAME.match(row["name"])
        if row.get("rc") != "0" or not os.path.isdir(folder) or not m:
            continue
        key = (m.group(1), m.group(2), int(m.group(3)), bool(m.group(4)))
        groups.setdefault(key, []).append(dict(row, folder=folder))
    return groups


def read_runs(path, scratch, startup=3, renumbered=False):
    """The runs of one archive (a .tar.gz or a folder), in runs.tsv's
    order, one per configuration: the medians over its rounds (the
    pressure iterations: their mean); those that did not end are left out;
    RENUMBERED: the renumbered runs (runTimed -renumber yes) instead of
    the plain ones."""
    root = archive_root(path, scratch)
    level = read_level(root)
    machine = read_ping_pong(os.path.join(root, "pingPong.log"))
    runs = []
    for (short, method, ranks, renum), rounds in read_rows(root).items():
        if renum != renumbered:
            continue
        skip = [int(row.get("startup", startup)) for row in rounds]
        medians = [read_medians(os.path.join(
            row["folder"], "postProcessing", "stepTimers"), k)
            for row, k in zip(rounds, skip)]
        logs = [os.path.join(row["folder"], "log.overPimpleDyMFoam")
                for row in rounds]
        runs.append(Run(
            level, short, method, ranks,
            {c: float(np.median([m[c] for m in medians]))
             for c in medians[0]},
            float(np.mean([pressure_iterations(log, k)
                           for log, k in zip(logs, skip)])),
            scalingModel.Decomposition.from_rank_report(
                rankTables.read_table(logs[0], "oversetRankReport")),
            machine))
    return runs


def read_archives(paths, startup=3):
    """The runs of every archive (unpacked in a scratch folder that is
    removed afterwards)."""
    with tempfile.TemporaryDirectory(prefix="flapfoam-validate-") as tmp:
        return [r for p in paths for r in read_runs(p, tmp, startup)]


def serial_costs(serial, cal):
    """The Costs of a level and stencil from its serial Run."""
    costs = scalingModel.Costs(serial.machine, (0.0, 0.0, 0.0), None, cal)
    n = float(serial.decomposition.cells.sum())
    costs.stencil = STENCILS[serial.stencil]
    costs.cCell = serial.measured["pimple"]/n
    costs.cWork = serial.measured["overset"]/n
    costs.rbd = serial.measured["rbd"]
    costs.iterations = serial.iterations
    costs.sBytes = 2*serial.iterations  # two sweeps per BiCGStab iteration
    return costs


def model_steps(runs, cal, measured_iterations=False):
    """{run name: the model's step} of every run with a serial run of its
    level and stencil among RUNS (ITERATIONS: the run's own counts rather
    than the model's G(P))."""
    serial = {(r.level, r.stencil): r for r in runs if r.ranks == 1}
    out = {}
    for r in runs:
        if (r.level, r.stencil) not in serial:
            continue
        costs = serial_costs(serial[(r.level, r.stencil)], cal)
        out[r.name] = scalingModel.predict(
            costs, r.decomposition,
            r.iterations if measured_iterations else None)
    return out


def select(runs, patterns):
    """The runs whose name (level/stencil-method-npN) matches a pattern
    (fnmatch), with the serial runs they need."""
    chosen = [r for r in runs
              if r.ranks > 1 and any(fnmatch.fnmatch(r.name, p)
                                     for p in patterns)]
    keys = {(r.level, r.stencil) for r in chosen}
    return [r for r in runs if r.ranks == 1
            and (r.level, r.stencil) in keys] + chosen


def fit_growth(runs):
    """growth: least squares of I/I1 - 1 = growth log2 P over the parallel
    runs (their serial run's I1)."""
    i1 = {(r.level, r.stencil): r.iterations for r in runs if r.ranks == 1}
    x = np.array([math.log2(r.ranks) for r in runs if r.ranks > 1])
    y = np.array([r.iterations/i1[(r.level, r.stencil)] - 1
                  for r in runs if r.ranks > 1])
    return float(x @ y/(x @ x))


def _log_fit(residual, start, bounds):
    from scipy.optimize import least_squares
    return least_squares(residual, start, bounds=bounds).x


def calibrate(runs, patterns=scalingModel.CALIBRATION_RUNS):
    """The Calibration fitted to the runs matching PATTERNS: growth to
    their pressure iterations; pSat and cIter to their PIMPLE (with their
    own iteration counts); vParallel and bStock to their overset part
    (log-ratio least squares)."""
    fit = select(runs, patterns)
    par = [r for r in fit if r.ranks > 1]
    base = scalingModel.CALIBRATION

    def cal_of(x):
        return dataclasses.replace(base, pSat=x[0], cIter=x[1],
                                   vParallel=x[2], bStock=x[3])

    def part(x, name, which):
        steps = model_steps(fit, cal_of(x), measured_iterations=True)
        return [math.log(steps[r.name][name]/r.measured[name])
                for r in par if which(r)]

    x = [base.pSat, base.cIter, base.vParallel, base.bStock]
    x[:2] = _log_fit(lambda y: part(list(y) + x[2:], "pimple",
                                    lambda r: True),
                     x[:2], ([1.0, 0.0], [1e3, 1e-2]))
    x[2:] = _log_fit(lambda y: part(x[:2] + list(y), "overset",
                                    lambda r: True),
                     x[2:], ([0.0, 0.0], [1.0, 1.0]))
    return dataclasses.replace(cal_of(x), growth=fit_growth(fit))


def rounded(cal):
    """CAL with 2-3 significant digits (as committed)."""
    return dataclasses.replace(
        cal, **{f.name: float("%.3g" % getattr(cal, f.name))
                for f in dataclasses.fields(cal)})


def compare(runs, cal, patterns=(), measured_iterations=False):
    """Rows (dict) of every parallel run with a model step: run, level,
    stencil, method, ranks, measured, model (steps, s), ratio,
    calibrated (whether it matched PATTERNS), and the parts."""
    steps = model_steps(runs, cal, measured_iterations)
    rows = []
    for r in runs:
        if r.ranks < 2 or r.name not in steps:
            continue
        m = steps[r.name]
        rows.append({
            "run": r.name, "level": r.level, "stencil": r.stencil,
            "method": r.method, "ranks": r.ranks,
            "measured": r.measured["step"], "model": m["total"],
            "ratio": m["total"]/r.measured["step"],
            "overset": (r.measured["overset"], m["overset"]),
            "pimple": (r.measured["pimple"], m["pimple"]),
            "calibrated": any(fnmatch.fnmatch(r.name, p) for p in patterns)})
    return rows


def largest_errors(rows):
    """{stencil: (largest |model/measured - 1|, its run)} and the same
    over all rows under the key None."""
    out = {}
    for key in sorted({r["stencil"] for r in rows}) + [None]:
        sub = [r for r in rows if key is None or r["stencil"] == key]
        worst = max(sub, key=lambda r: abs(r["ratio"] - 1))
        out[key] = (abs(worst["ratio"] - 1), worst["run"])
    return out


def ranking(rows, by):
    """{(level, stencil, ranks): methods from fastest to slowest} by the
    rows' BY ("measured" or "model"), where two methods or more ran."""
    groups = {}
    for r in rows:
        groups.setdefault((r["level"], r["stencil"], r["ranks"]),
                          []).append(r)
    return {k: [r["method"] for r in sorted(g, key=lambda r: r[by])]
            for k, g in groups.items() if len(g) > 1}


def table(rows, markdown=False):
    """Lines of the comparison: one per run, then the largest errors per
    stencil, the rankings and the last line 'model within X % of N
    measured runs'."""
    head = ("level", "stencil", "method", "np", "measured [s]", "model [s]",
            "model/measured", "overset meas/model", "pimple meas/model",
            "fit")
    fmt = "| " + " | ".join(["%s"]*len(head)) + " |" if markdown else \
        "%-7s %-7s %-13s %3s %13s %10s %15s %19s %18s %4s"
    lines = [fmt % head]
    if markdown:
        lines.append("|---|---|---|---:|---:|---:|---:|---:|---:|---|")
    for r in rows:
        lines.append(fmt % (
            r["level"], r["stencil"], r["method"], r["ranks"],
            "%.3f" % r["measured"], "%.3f" % r["model"],
            "%.2f (%+.0f %%)" % (r["ratio"], 100*(r["ratio"] - 1)),
            "%.3f / %.3f" % r["overset"], "%.3f / %.3f" % r["pimple"],
            "cal" if r["calibrated"] else "held"))
    worst = largest_errors(rows)
    lines.append("")
    for key in sorted(k for k in worst if k is not None):
        lines.append("largest error %s: %.0f %% (%s)" % (
            key, 100*worst[key][0], worst[key][1]))
    measured, model = ranking(rows, "measured"), ranking(rows, "model")
    for k in sorted(measured):
        lines.append("ranking %s %s np %d: measured %s, model %s%s" % (
            k + (" < ".join(measured[k]), " < ".join(model[k]),
                 "" if measured[k] == model[k] else "  (differs)")))
    lines.append("model within %.0f %% of %d measured runs"
                 % (100*worst[None][0], len(rows)))
    return lines
