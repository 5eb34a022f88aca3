# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The scaling model (flapfoam.scaling.model) against timed runs: read the
archives of bench/scaling/measured (a .tar.gz of one level or several, or
a folder with runs.tsv, pingPong.log and runs/<stencil>-<method>-np<N>/,
or one holding such level folders), the medians over other rounds of a
session (runTimed logs, summary.txt: flapfoam.bench.timed_rounds) in place of
one round's, calibrate the model's constants on some of the runs,
compare its step with every run's, and the causes of one partition's
PIMPLE against another's (flapfoam.scaling.causes).  numpy; scipy for
calibrate.

A run's measured step: rbd + overset + pimple of the step timers (max
over ranks), the median over the steps after the start-up ones (runs.tsv);
its pressure iterations: the PBiCGStab solves of p per step in its log,
the mean over the same steps; its ranks: the solver's oversetRankReport.
The model's inputs: that report, the serial run of the same session
(archive), level and stencil (cCell, cWork, rbd, serial iterations) and
the ping-pong.

The command line:

    flapfoam scaling_validate [ARCHIVE ...] [-rounds FILE ...]
        [-levels "coarse medium"] [-calibrate PATTERN ...]
        [-measuredIterations] [-o FILE] [-causes FILE]

ARCHIVE: a .tar.gz of one level or several (t3/coarse, t3/medium: every
level in it) in the format of bench/scaling/measured, or a folder with
runs.tsv, pingPong.log and runs/ (a level folder or one holding several).
Default: every committed session, both 16-core ones:
measured/scaling-16core-{coarse,medium}.tar.gz (one round) and
measured/device-2026-11-26/session2-round3.tar.gz with -rounds
measured/device-2026-11-26/session1/runTimed.log (rounds 1 and 2).
-rounds: runTimed logs (their summary tables in the order of -levels) or
summary.txt files of other rounds of the last ARCHIVE's session: the
medians over the rounds (the archive's own summary.txt are one round)
replace the measured step, rbd, overset and pimple of the matching runs
(level, stencil, method, np) of the archives with that session's
ping-pong; the rank reports and iterations stay those of the archive's
logs (the decompositions are the same in every round).
Prints per run (np >= 2) session, level, stencil, method, np, rounds,
measured and model step, their ratio; the largest errors (fitted, held
out), the rankings, the pairs of methods measured more than the
round-to-round spread (15 %) apart and whether the model orders them so,
and last "model within X % of N measured runs".  -calibrate: fit the
constants on the runs matching the patterns ([session:]level/stencil-
method-npN, fnmatch; "default": the committed set) instead of using the
committed ones.  -o: also a markdown table; -causes: the PIMPLE gap of
each method against the fastest one, cause by cause (markdown).
"""

import argparse
import dataclasses
import fnmatch
import glob
import io
import math
import os
import re
import tarfile
import tempfile

import numpy as np

from flapfoam.errors import run_tool
from flapfoam.paths import project_path
from flapfoam.bench import rank_tables, timed_rounds
from flapfoam.io import solver_log, step_timers
from flapfoam.scaling import causes as scaling_causes
from flapfoam.scaling import model as scaling_model

LEVELS = ("coarse", "medium", "fine")
PARTS = ("rbd", "overset", "pimple", "pimpleOversetInterpolate",
         "oversetStencilVoxels")


@dataclasses.dataclass
class Run:
    """One timed run: level, stencil (short: octree, ID), method, ranks,
    measured (medians of PARTS and "step"), iterations (pressure, per
    step), decomposition (scaling_model.Decomposition), machine (alpha,
    beta), session (the archive's label) and rounds (how many rounds the
    measured medians are over)."""
    level: str
    stencil: str
    method: str
    ranks: int
    measured: dict
    iterations: float
    decomposition: scaling_model.Decomposition
    machine: tuple
    session: str = ""
    rounds: int = 1

    @property
    def short(self):
        """level/stencil-method-npN (what calibration patterns match)."""
        return "%s/%s-%s-np%d" % (self.level, self.stencil, self.method,
                                  self.ranks)

    @property
    def name(self):
        """session:level/stencil-method-npN (unique over sessions)."""
        return "%s:%s" % (self.session, self.short)

    @property
    def group(self):
        """(session, level, stencil): the runs that share a serial run."""
        return (self.session, self.level, self.stencil)


def matches(run, patterns):
    """Whether RUN's name or short name matches a pattern (fnmatch)."""
    return any(fnmatch.fnmatch(run.short, p) or fnmatch.fnmatch(run.name, p)
               for p in patterns)


def archive_roots(path, scratch):
    """The level folders (those holding runs.tsv, outside runs/) of an
    archive: a .tar.gz (unpacked under SCRATCH) or a folder, with one
    level or several (t3/coarse, t3/medium)."""
    if os.path.isfile(path):
        out = os.path.join(scratch, os.path.basename(path).split(".")[0])
        with tarfile.open(path) as tar:
            if hasattr(tarfile, "data_filter"):
                tar.extractall(out, filter="data")
            else:
                tar.extractall(out)
        path = out
    found = sorted(os.path.dirname(f) for f in glob.glob(
        os.path.join(path, "**", "runs.tsv"), recursive=True))
    roots = [f for f in found if not any(
        f.startswith(os.path.join(g, "runs") + os.sep) for g in found)]
    if not roots:
        raise ValueError("%s: no runs.tsv" % path)
    return roots


def session_label(path):
    """A short label of an archive: its file name less .tar.gz and a
    trailing -<level>, or the folder's name (a level folder's parent's)."""
    path = os.path.abspath(path)
    if os.path.isfile(path):
        name = os.path.basename(path).split(".")[0]
        return re.sub(r"-(%s)$" % "|".join(LEVELS), "", name)
    name = os.path.basename(path)
    if os.path.isfile(os.path.join(path, "runs.tsv")) \
            and name in LEVELS:
        return os.path.basename(os.path.dirname(path))
    return re.sub(r"-(%s)$" % "|".join(LEVELS), "", name)


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
    counts = [row[2] for row in solver_log.read_log(log)]
    return float(np.mean(counts[startup:]))


def read_medians(folder, startup):
    """Medians over the timed steps of PARTS and of the step (rbd +
    overset + pimple per step)."""
    columns, data = step_timers.read_input(folder, startup)
    col = {c: data[:, i] for i, c in enumerate(columns)}
    zero = np.zeros(len(data))
    out = {p: float(np.median(col.get(p, zero))) for p in PARTS}
    out["step"] = float(np.median(col["rbd"] + col["overset"]
                                  + col["pimple"]))
    return out


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
        m = timed_rounds.NAME.match(row["name"])
        if row.get("rc") != "0" or not os.path.isdir(folder) or not m:
            continue
        key = (m.group(1), m.group(2), int(m.group(3)), bool(m.group(4)))
        groups.setdefault(key, []).append(dict(row, folder=folder))
    return groups


def read_level_runs(root, session, startup=3, renumbered=False):
    """The runs of one level folder, in runs.tsv's order, one per
    configuration: the medians over its rounds (the pressure iterations:
    their mean); those that did not end are left out; RENUMBERED: the
    renumbered runs (runTimed -renumber yes) instead of the plain ones."""
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
            scaling_model.Decomposition.from_rank_report(
                rank_tables.read_table(logs[0], "oversetRankReport")),
            machine, session, len(rounds)))
    return runs


def read_runs(path, scratch, startup=3, renumbered=False):
    """The runs of every level folder of one archive (a .tar.gz or a
    folder), labelled with session_label(PATH); see read_level_runs."""
    return [r for root in archive_roots(path, scratch)
            for r in read_level_runs(root, session_label(path), startup,
                                     renumbered)]


def own_rounds(path, scratch):
    """[(text of summary.txt or "", level, ping-pong log's text)] of every
    level folder of an archive: each summary is one round of its runs,
    the ping-pong the session's fingerprint."""
    out = []
    for root in archive_roots(path, scratch):
        texts = []
        for name in ("summary.txt", "pingPong.log"):
            fname = os.path.join(root, name)
            with open(fname) if os.path.isfile(fname) else \
                    io.StringIO("") as f:
                texts.append(f.read())
        out.append((texts[0], read_level(root), texts[1]))
    return out


def rounds_of(tables, files, level_names=("coarse", "medium")):
    """{(level, stencil, method, ranks): (medians of step, rbd, overset,
    pimple over the rounds, rounds)} of TABLES [(summary text, level)]
    and FILES (runTimed logs, their tables in the order of LEVEL_NAMES, or
    summary.txt; flapfoam.bench.timed_rounds), every text counted once."""
    texts = {}
    for text, level in tables:
        texts.setdefault(text, timed_rounds.read_tables(text, [level]))
    for fname in files:
        with open(fname) as f:
            text = f.read()
        if text not in texts:
            texts[text] = timed_rounds.read_file(fname, list(level_names))
    timed = [t for found in texts.values() for t in found]
    return {k[:4]: v for k, v in timed_rounds.medians(
        [t for t in timed if not t.renumbered]).items()}


def apply_rounds(runs, table):
    """RUNS with the measured step, rbd, overset and pimple of the
    configurations in TABLE (rounds_of) replaced by its medians over the
    rounds, and their rounds count; the rest of each run (its rank
    report, iterations, the other parts) kept."""
    out = []
    for r in runs:
        found = table.get((r.level, r.stencil, r.method, r.ranks))
        if found:
            parts, count = found
            r = dataclasses.replace(r, measured=dict(r.measured, **parts),
                                    rounds=count)
        out.append(r)
    return out


def read_archives(paths, startup=3, rounds=(), level_names=("coarse",
                                                            "medium")):
    """The runs of every archive (unpacked in a scratch folder that is
    removed afterwards).  ROUNDS: runTimed logs or summary.txt files of
    other rounds of the session of the last archive in PATHS; they apply
    to the archives with that one's ping-pong (one session's level
    folders share it), whose own summary.txt count as one round each."""
    with tempfile.TemporaryDirectory(prefix="flapfoam-validate-") as tmp:
        runs = [read_runs(p, tmp, startup) for p in paths]
        if not rounds:
            return [r for group in runs for r in group]
        own = [own_rounds(p, tmp) for p in paths]
        pings = {o[2] for o in own[-1]}
        session = [k for k, o in enumerate(own) if {x[2] for x in o} <= pings]
        table = rounds_of([x[:2] for k in session for x in own[k] if x[0]],
                          rounds, level_names)
        return [r for k, group in enumerate(runs)
                for r in (apply_rounds(group, table) if k in session
                          else group)]


def model_steps(runs, cal, measured_iterations=False):
    """{run name: the model's step} of every run with a serial run of its
    session, level and stencil among RUNS (ITERATIONS: the run's own
    counts rather than the model's G(P))."""
    serial = {r.group: r for r in runs if r.ranks == 1}
    out = {}
    for r in runs:
        if r.group not in serial:
            continue
        costs = scaling_model.serial_costs(serial[r.group], cal)
        out[r.name] = scaling_model.predict(
            costs, r.decomposition,
            r.iterations if measured_iterations else None)
    return out


def select(runs, patterns):
    """The runs whose name (level/stencil-method-npN) matches a pattern
    (fnmatch), with the serial runs they need."""
    chosen = [r for r in runs if r.ranks > 1 and matches(r, patterns)]
    keys = {r.group for r in chosen}
    return [r for r in runs if r.ranks == 1 and r.group in keys] + chosen


def fit_growth(runs):
    """growth: least squares of I/I1 - 1 = growth log2 P over the parallel
    runs (their serial run's I1)."""
    i1 = {r.group: r.iterations for r in runs if r.ranks == 1}
    x = np.array([math.log2(r.ranks) for r in runs if r.ranks > 1])
    y = np.array([r.iterations/i1[r.group] - 1
                  for r in runs if r.ranks > 1])
    return float(x @ y/(x @ x))


def _log_fit(residual, start, bounds):
    from scipy.optimize import least_squares
    return least_squares(residual, start, bounds=bounds).x


# where calibrate's least squares start
START = scaling_model.Calibration(p_sat=14.0, c_iter=2e-5, growth=0.06,
                                 v_parallel=0.025, b_stock=0.1)


def calibrate(runs, patterns=scaling_model.CALIBRATION_RUNS):
    """The Calibration fitted to the runs matching PATTERNS: growth to
    their pressure iterations; pSat and cIter to their PIMPLE (with their
    own iteration counts); vParallel and bStock to their overset part
    (log-ratio least squares)."""
    fit = select(runs, patterns)
    par = [r for r in fit if r.ranks > 1]
    base = START

    def cal_of(x):
        return dataclasses.replace(base, p_sat=x[0], c_iter=x[1],
                                   v_parallel=x[2], b_stock=x[3])

    def part(x, name, which):
        steps = model_steps(fit, cal_of(x), measured_iterations=True)
        return [math.log(steps[r.name][name]/r.measured[name])
                for r in par if which(r)]

    x = [base.p_sat, base.c_iter, base.v_parallel, base.b_stock]
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
    """Rows (dict) of every parallel run with a model step: run, session,
    level, stencil, method, ranks, rounds, measured, model (steps, s), ratio,
    calibrated (whether it matched PATTERNS), and the parts."""
    steps = model_steps(runs, cal, measured_iterations)
    rows = []
    for r in runs:
        if r.ranks < 2 or r.name not in steps:
            continue
        m = steps[r.name]
        rows.append({
            "run": r.name, "session": r.session, "level": r.level,
            "stencil": r.stencil, "method": r.method, "ranks": r.ranks,
            "rounds": r.rounds,
            "measured": r.measured["step"], "model": m["total"],
            "ratio": m["total"]/r.measured["step"],
            "overset": (r.measured["overset"], m["overset"]),
            "pimple": (r.measured["pimple"], m["pimple"]),
            "calibrated": matches(r, patterns)})
    return rows


def largest_errors(rows, key=lambda r: r["stencil"]):
    """{KEY of a row (default: its stencil): (largest |model/measured -
    1|, its run)} and the same over all rows under the key None."""
    out = {}
    for k in sorted({key(r) for r in rows}) + [None]:
        sub = [r for r in rows if k is None or key(r) == k]
        worst = max(sub, key=lambda r: abs(r["ratio"] - 1))
        out[k] = (abs(worst["ratio"] - 1), worst["run"])
    return out


def ranking(rows, by):
    """{(session, level, stencil, ranks): methods from fastest to
    slowest} by the rows' BY ("measured" or "model"), where two methods
    or more ran."""
    groups = {}
    for r in rows:
        groups.setdefault((r["session"], r["level"], r["stencil"],
                           r["ranks"]), []).append(r)
    return {k: [r["method"] for r in sorted(g, key=lambda r: r[by])]
            for k, g in groups.items() if len(g) > 1}


# the round-to-round spread of one configuration on the 16-core machine
# (median max/min of three rounds: 1.15): pairs of methods measured
# closer than that cannot be ranked
SPREAD = 0.15


def ranked_pairs(rows, spread=SPREAD):
    """[(run a, run b, measured b/a, whether the model orders them as
    measured, session)] of the pairs of methods at the same session,
    level, stencil and ranks whose measured steps differ by more than
    SPREAD (a the faster)."""
    keys = ("session", "level", "stencil", "ranks")
    out = []
    for i, x in enumerate(rows):
        for y in rows[i + 1:]:
            if [x[k] for k in keys] != [y[k] for k in keys]:
                continue
            a, b = sorted((x, y), key=lambda r: r["measured"])
            ratio = b["measured"]/a["measured"]
            if ratio > 1 + spread:
                out.append((a["run"], b["run"], ratio,
                            a["model"] < b["model"], a["session"]))
    return out


def table_lines(rows, markdown=False):
    """One line per run (and a markdown table's head)."""
    head = ("session", "level", "stencil", "method", "np", "rounds",
            "measured [s]", "model [s]", "model/measured",
            "overset meas/model", "pimple meas/model", "fit")
    fmt = "| " + " | ".join(["%s"]*len(head)) + " |" if markdown else \
        "%-15s %-6s %-6s %-12s %2s %6s %12s %9s %14s %17s %17s %4s"
    lines = [fmt % head]
    if markdown:
        lines.append("|---|---|---|---|---:|---:|---:|---:|---:|---:|---:"
                     "|---|")
    for r in rows:
        lines.append(fmt % (
            r["session"], r["level"], r["stencil"], r["method"], r["ranks"],
            r["rounds"], "%.3f" % r["measured"], "%.3f" % r["model"],
            "%.2f (%+.0f %%)" % (r["ratio"], 100*(r["ratio"] - 1)),
            "%.3f / %.3f" % r["overset"], "%.3f / %.3f" % r["pimple"],
            "cal" if r["calibrated"] else "held"))
    return lines


def table(rows, markdown=False):
    """Lines of the comparison: one per run, then the largest errors per
    session and stencil (fitted and held out), the rankings, the pairs
    measured further apart than the spread and the last line 'model
    within X % of N measured runs'."""
    lines = table_lines(rows, markdown) + [""]
    for fit in (True, False):
        sub = [r for r in rows if r["calibrated"] == fit]
        worst = largest_errors(sub, lambda r: (r["session"], r["stencil"])) \
            if sub else {}
        for k in sorted(k for k in worst if k is not None):
            lines.append("largest error %s %s %s: %.0f %% (%s)" % (
                "fitted" if fit else "held out", k[0], k[1],
                100*worst[k][0], worst[k][1]))
    measured, model = ranking(rows, "measured"), ranking(rows, "model")
    for k in sorted(measured):
        lines.append("ranking %s %s %s np %d: measured %s, model %s%s" % (
            k + (" < ".join(measured[k]), " < ".join(model[k]),
                 "" if measured[k] == model[k] else "  (differs)")))
    pairs = ranked_pairs(rows)
    for a, b, ratio, ok, _s in pairs:
        if not ok:
            lines.append("pair ranked otherwise: %s < %s (measured %.2fx)"
                         % (a, b, ratio))
    for session in sorted({p[4] for p in pairs}) + [None]:
        sub = [p for p in pairs if session in (None, p[4])]
        lines.append("pairs measured more than %.0f %% apart%s: %d of %d "
                     "ranked as measured" % (
                         100*SPREAD, " in " + session if session else "",
                         sum(p[3] for p in sub), len(sub)))
    lines.append("model within %.0f %% of %d measured runs"
                 % (100*largest_errors(rows)[None][0], len(rows)))
    return lines


MEASURED = project_path("bench", "scaling", "measured")
SESSIONS = [os.path.join(MEASURED, f) for f in (
    "scaling-16core-coarse.tar.gz", "scaling-16core-medium.tar.gz",
    "device-2026-11-26/session2-round3.tar.gz")]
ROUNDS = [os.path.join(MEASURED, "device-2026-11-26/session1/runTimed.log")]


def arguments(argv=None):
    parser = argparse.ArgumentParser(
        prog="flapfoam scaling_validate",
        description="The scaling model against measured runs.")
    parser.add_argument("archives", nargs="*")
    parser.add_argument("-rounds", nargs="+", metavar="FILE", default=[])
    parser.add_argument("-levels", default="coarse medium")
    parser.add_argument("-calibrate", nargs="+", metavar="PATTERN")
    parser.add_argument("-measuredIterations", dest="measured_iterations",
                        action="store_true")
    parser.add_argument("-o", metavar="FILE")
    parser.add_argument("-causes", metavar="FILE")
    args = parser.parse_args(argv)
    if not args.archives:
        args.archives, args.rounds = SESSIONS, args.rounds or ROUNDS
    return args


def main(argv=None):
    args = arguments(argv)
    runs = read_archives(args.archives, rounds=args.rounds,
                         level_names=args.levels.split())
    patterns = scaling_model.CALIBRATION_RUNS
    cal = scaling_model.CALIBRATION
    if args.calibrate:
        if args.calibrate != ["default"]:
            patterns = tuple(args.calibrate)
        cal = rounded(calibrate(runs, patterns))
    print("calibration: %s\ncalibrated on: %s" % (cal, " ".join(patterns)))
    rows = compare(runs, cal, patterns, args.measured_iterations)
    print("\n".join(table(rows)))
    if args.o:
        with open(args.o, "w") as f:
            f.write("\n".join(table(rows, markdown=True)) + "\n")
    if args.causes:
        with open(args.causes, "w") as f:
            f.write("\n".join(scaling_causes.report(runs, cal)) + "\n")


if __name__ == "__main__":
    run_tool(main)
