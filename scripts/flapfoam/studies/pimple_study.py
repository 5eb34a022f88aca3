# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The table of the PIMPLE study (bench/pimple/run): per level, rank count and
setting, what a simulated flapping cycle cost and how far its flight is
from the paper's settings on the same mesh (the accuracy guard,
flapfoam.checks.pimple_guard).

    flapfoam pimple_study DIR [-cycles N] [-reference NAME]
                                    [-o OUT.md]
    flapfoam pimple_study DIR -steps K -settings NAME...
                                    [-o OUT.md]

DIR holds the runs <level>-np<N>-<setting> (bench/pimple/run) and, for
each, <run>.settings: the dictionary edits of the setting (a "FILE ENTRY
VALUE" line each).  Per run: steps of the cycle(s), wall seconds (the step
timers' total) and CPU seconds (the solver's ExecutionTime) per cycle, the
cost ratio to the reference setting (default paper) of its level and
ranks, pressure iterations a step, and the guard: each criterion's
measured share of what it allows (100 % at the limit) and PASS/FAIL.

With -steps K: the fixed-step runs <level>-np<N>-<setting>-r<round> of
bench/pimple/run -steps instead: per run the median per step of every
step-timer column after K start-up steps, then the median over the rounds;
the table gives the step, pimple and its split (step_timers.pimple_split)
per level, ranks and setting (in the order of -settings), and the step's
and pimple's ratio of the first setting's to this one's.
"""

import argparse
import dataclasses
import os
import re
import sys

import numpy as np

from flapfoam.checks import pimple_guard
from flapfoam.io import step_timers
from flapfoam.errors import FlapFoamError, run_tool

RUN = re.compile(r"^(\w+)-np(\d+)-([\w.+]+)$")
STEPS_RUN = re.compile(r"^(\w+)-np(\d+)-([\w.+]+)-r(\d+)$")


@dataclasses.dataclass
class StudyRun:
    """A run of the study and its measured cycle(s)."""
    level: str
    ranks: int
    setting: str
    edits: list
    cycles: pimple_guard.Cycles


def read_settings(path):
    """The "FILE ENTRY VALUE" lines of a .settings file (none if absent)."""
    if not os.path.isfile(path):
        return []
    with open(path) as fh:
        return [line.strip() for line in fh
                if line.strip() and not line.startswith("#")]


def read_runs(folder, n_cycles):
    """The completed runs of DIR (a run short of the cycles is reported
    and left out)."""
    runs = []
    for name in sorted(os.listdir(folder)):
        m = RUN.match(name)
        path = os.path.join(folder, name)
        if not (m and os.path.isdir(path)):
            continue
        try:
            cycles = pimple_guard.read_run(path, n_cycles)
        except (FlapFoamError, OSError, KeyError, ValueError) as err:
            print("pimple_study: %s left out: %s" % (name, err))
            continue
        runs.append(StudyRun(m.group(1), int(m.group(2)), m.group(3),
                             read_settings(path + ".settings"), cycles))
    return runs


def row(run, ref, n_cycles):
    """The table line of a run against its reference."""
    c, r = run.cycles, ref.cycles
    checks = pimple_guard.guard(r, c)
    shares = " | ".join("%.0f %%" % (100*k.ratio) for k in checks)
    judged = [k for k in checks if k.counts]
    verdict = "reference" if run is ref else (
        "PASS" if all(k.ok for k in judged) else "FAIL (%s)" % ", ".join(
            k.name for k in judged if not k.ok))
    return ("| %s | %d | %s | %d | %.0f | %.0f | %.2f | %.1f | %s | %s |"
            % (run.level, run.ranks, run.setting, c.steps/n_cycles,
               c.wall/n_cycles, c.cpu/n_cycles, r.cpu/c.cpu,
               c.p_iterations, shares, verdict))


def table(runs, reference, n_cycles):
    """The markdown lines: one row per run, grouped by level and ranks."""
    lines = [
        "| level | ranks | setting | steps a cycle | wall [s] a cycle | "
        "CPU [s] a cycle | cost: %s CPU / this | p iterations a step | "
        "mean C_xI | mean C_zI | C_zI(t) | C_zI(t) smoothed | x | z | "
        "continuity | guard |" % reference,
        "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        "---:|---:|---|",
    ]
    groups = {}
    for run in runs:
        groups.setdefault((run.level, run.ranks), []).append(run)
    missing = []
    for key in sorted(groups):
        refs = [r for r in groups[key] if r.setting == reference]
        if not refs:
            missing.append("%s np%d" % key)
            continue
        for run in sorted(groups[key], key=lambda r: r.setting != reference):
            lines.append(row(run, refs[0], n_cycles))
    if missing:
        lines.append("")
        lines.append("No %s run (reference) for: %s" % (reference,
                                                       ", ".join(missing)))
    return lines


def settings_lines(runs):
    """What each setting changes (its .settings lines)."""
    seen = {}
    for run in runs:
        seen.setdefault(run.setting, run.edits)
    return ["- `%s`: %s" % (name, "; ".join("`%s`" % e for e in edits)
                            if edits else "the case's dictionaries")
            for name, edits in sorted(seen.items())]


def step_medians(folder, startup):
    """{(level, ranks, setting): {column: median over the rounds of the
    per-run medians}} of the fixed-step runs in folder."""
    per_round = {}
    for name in sorted(os.listdir(folder)):
        m = STEPS_RUN.match(name)
        if not (m and os.path.isdir(os.path.join(folder, name))):
            continue
        columns, data = step_timers.read_input(
            os.path.join(folder, name, "postProcessing", "stepTimers"),
            startup)
        key = (m.group(1), int(m.group(2)), m.group(3))
        per_round.setdefault(key, []).append(
            {c: float(np.median(data[:, i])) for i, c in enumerate(columns)})
    return {key: {c: float(np.median([r[c] for r in rounds]))
                  for c in set.intersection(*(set(r) for r in rounds))}
            for key, rounds in per_round.items()}, \
        {key: len(rounds) for key, rounds in per_round.items()}


def steps_table(medians, rounds, settings):
    """The markdown lines of the per-step table."""
    lines = [
        "| level | ranks | setting | rounds | step [s] | pimple [s] | "
        "momentum | pressure (solves) | turbulence | interpolate (calls) | "
        "p iterations | step: first / this | pimple: first / this |",
        "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for level, ranks in sorted({k[:2] for k in medians}):
        first = None
        for setting in settings:
            m = medians.get((level, ranks, setting))
            if m is None:
                continue
            first = first or m
            s = step_timers.pimple_split(m) or {}
            lines.append(
                "| %s | %d | %s | %d | %.4f | %.4f | %s | %s | %s | %s | %s | "
                "%.2f | %.2f |" % (
                    level, ranks, setting, rounds[(level, ranks, setting)],
                    m["total"], m["pimple"], fmt(s, "momentum"),
                    "%s (%s)" % (fmt(s, "pressure"), fmt(s, "pressureSolve")),
                    fmt(s, "turbulence"),
                    "%s (%s)" % (fmt(s, "interpolate"),
                                 fmt(s, "interpolations", "%.0f")),
                    fmt(s, "pIterations", "%.0f"),
                    first["total"]/m["total"], first["pimple"]/m["pimple"]))
    return lines


def fmt(values, key, form="%.4f"):
    """A value of the split, or '-' without the split."""
    return form % values[key] if key in values else "-"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("dir", help="the study's folder (bench/pimple/run -dir)")
    ap.add_argument("-cycles", type=float, default=1,
                    help="whole cycles from the start (default 1)")
    ap.add_argument("-reference", default="paper",
                    help="the setting the others are guarded against")
    ap.add_argument("-o", dest="out", help="write the table here too")
    ap.add_argument("-steps", type=int, metavar="K",
                    help="the fixed-step runs' table, K start-up steps")
    ap.add_argument("-settings", nargs="+", default=[],
                    help="with -steps: the settings, in the table's order")
    args = ap.parse_args(argv)
    if args.steps is not None:
        medians, rounds = step_medians(args.dir, args.steps)
        if not medians:
            sys.exit("pimple_study: no run <level>-np<N>-<setting>-r<round> "
                     "in " + args.dir)
        return write(steps_table(medians, rounds, args.settings or sorted(
            {k[2] for k in medians})) + [
            "", "Medians per step after %d start-up steps, then over the "
            "rounds (wall-clock seconds; in parallel the maximum over the "
            "ranks)." % args.steps], args.out)
    runs = read_runs(args.dir, args.cycles)
    if not runs:
        sys.exit("pimple_study: no completed run <level>-np<N>-<setting> in "
                 + args.dir)
    lines = table(runs, args.reference, args.cycles) + [
        "", "Guard columns: the measured difference as a share of what "
        "the guard allows (mean C_xI, C_zI: 1 % of the larger mean; "
        "C_zI(t): 3 % of its range, step by step and averaged over 1 % of "
        "the cycle; x, z after the cycle: 1 % of the excursion; "
        "continuity: the reference's error); at most 100 % passes.  The "
        "step-by-step C_zI(t) is informative, not in the verdict: the "
        "overset's single-step spikes of C_zI reach about a quarter of its "
        "range, at times that move with the steps (flapfoam.checks.pimple_guard).",
        "",
        "Settings:"] + settings_lines(runs)
    return write(lines, args.out)


def write(lines, out):
    """Print the lines, and write them to out if given."""
    print("\n".join(lines))
    if out:
        with open(out, "w") as fh:
            fh.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(run_tool(main))
