# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Trim in CFD: a quasi-steady (QS) trim corrected by short CFD runs until the
CFD holds the drone: the mean forces balance the weight and the body's
pitch stays.

    flapfoam cfd_trim -dir DIR [-case cases/bodyWingDrone] [-variant hover]
        [-level tiny] [-np 2] [-cycles 3] [-average 2] [-maxRuns 6]
        [-forceTolerance 0.02] [-pitchTolerance 0.2] [-fdStep 0.01]
        [-model cfd|quasiSteady] [-start ENTRY.KEY=V,...] [-o PREFIX]
        [-summary FILE]

Variables: those of the case's system/trimDict (flapfoam trim), their start
values the variant's (-variant, a flapfoam trim -write: the QS trim, whose
initial state every run starts from) or -start's.  Run k (DIR/run-k): Allrun -level L
-variant V -cycles N -np P -noPlot -case DIR/run-k with -set of the
variables' values.  Its residuals over its last -average cycles (the first
ones hold the flow's start): the mean fluid force on all bodies over the
weight, r_z = F_z/W - 1 and r_x = F_x/W, and the body's pitch change per
cycle r_theta [deg] (the body of the trimDict's... the -pitchBody, default
body, its orientation's pitch).  Converged when |r_z|, |r_x| <=
-forceTolerance and |r_theta| <= -pitchTolerance.  Else the next values:
the Gauss-Newton step on the scaled residuals (r_z, r_x, r_theta
forceTolerance/pitchTolerance: each tolerance the same size) with the QS
Jacobian, the same residuals of the QS model flown the same way (Allrun
-model quasiSteady, the same cycles) at the start values and each
variable moved by -fdStep (in the variable's range: (max - min) fdStep),
kept inside the trimDict's ranges.  -model quasiSteady: every run on the
QS model (the procedure in seconds; it converges at once from a QS trim).

An interrupted trim continues where it stopped: the runs are a function of
the earlier ones, so a run folder that reaches its cycles is read again,
one that does not is continued by its Allrun (the restart), and the next
ones follow.  Prints a line per run; -o PREFIX: PREFIX.json (the runs, the
Jacobian) and PREFIX.png (the residuals per run); -summary FILE: the keys
cfd_trim_runs, cfd_trim_converged, cfd_trim_force_residual_over_weight (the
largest of |r_z|, |r_x| of the last run), cfd_trim_pitch_change_deg_per_
cycle, cfd_trim_variables merged into FILE.  Exit status 1 if the last
run is not converged.  numpy, h5py, matplotlib.
"""

import argparse
import json
import math
import os
import subprocess
import sys
import time
from dataclasses import dataclass, field

import numpy as np

from flapfoam.errors import FlapFoamError, run_tool
from flapfoam.io import run_series
from flapfoam.paths import project_path
from flapfoam.studies.cycle_map import read_edits
from flapfoam.studies.power import Drone, mean_over
from flapfoam.studies.qs_case import StudyError, write_summary
from flapfoam.studies.trim import read_trim_dict

DICT = "constant/dynamicMeshDict"
MOTIONS = "eABAMeshMotionCoeffs/imposedMotion"


@dataclass
class Settings:
    """The case, its variant and how each run is flown, the tolerances,
    and the folder of the runs."""
    dir: str
    case: str = project_path("cases", "bodyWingDrone")
    variant: str = "hover"
    level: str = "tiny"
    np: int = 2
    cycles: int = 3
    average: int = 2
    max_runs: int = 6
    force_tolerance: float = 0.02
    pitch_tolerance: float = 0.2
    fd_step: float = 0.01
    model: str = "cfd"
    pitch_body: str = "body"
    start: dict = field(default_factory=dict)


@dataclass
class Run:
    """One run: the variables' values, its residuals (r_z, r_x, r_theta)
    and its folder and wall time."""
    values: list
    residuals: list
    folder: str
    seconds: float

    def converged(self, s):
        rz, rx, rt = self.residuals
        return max(abs(rz), abs(rx)) <= s.force_tolerance and \
            abs(rt) <= s.pitch_tolerance


@dataclass
class Problem:
    """The variables (ENTRY.KEY), their ranges and start values."""
    names: list
    ranges: list
    start: list
    runs: list = field(default_factory=list)
    jacobian: np.ndarray = None


def problem_of(s):
    """The trimDict's variables and the variant's values of them."""
    ranges = read_trim_dict(os.path.join(s.case, "system", "trimDict"))
    edits = {(f, e): v for f, e, v in
             read_edits(os.path.join(s.case, "variants", s.variant))}
    start = []
    for name in ranges:
        entry, key = name.split(".")
        where = (DICT, "%s/%s/%s" % (MOTIONS, entry, key))
        if where not in edits:
            raise StudyError("variants/%s: no line %s %s (allowed: a trim's"
                             " variant, flapfoam trim -write, which sets"
                             " every variable of system/trimDict)"
                             % (s.variant, *where))
        start.append(s.start.pop(name, None) or float(edits[where]))
    if s.start:
        raise StudyError("-start %s: not a variable of system/trimDict"
                         " (allowed: %s)" % (" ".join(s.start),
                                             " ".join(ranges)))
    return Problem(list(ranges), list(ranges.values()), start)


def command(s, problem, values, folder, model):
    """The Allrun command of a run."""
    cmd = [os.path.join(s.case, "Allrun"), "-variant", s.variant,
           "-cycles", str(s.cycles), "-case", folder, "-noPlot"]
    if model == "cfd":
        cmd += ["-level", s.level] + (["-np", str(s.np)] if s.np > 1 else [])
    else:
        cmd += ["-model", "quasiSteady"]
    for name, v in zip(problem.names, values):
        entry, key = name.split(".")
        cmd += ["-set", DICT, "%s/%s/%s" % (MOTIONS, entry, key), repr(v)]
    return cmd


def finished(folder, s):
    """The run's flight data reaches its last cycle's end."""
    try:
        period = Drone(folder, "flapping").period
        t = run_series.read(folder).time
    except (OSError, KeyError, FlapFoamError):  # not started, no rows yet
        return False
    return t[-1] >= s.cycles*period*(1 - 1e-9)


def residuals(folder, s):
    """(r_z, r_x, r_theta) of a finished run (module docstring)."""
    drone = Drone(folder, "flapping")
    series = run_series.read(folder)
    t1 = s.cycles*drone.period
    t0 = t1 - s.average*drone.period
    force = sum(b.force for b in series.bodies.values()
                if b.force is not None)
    good = np.all(np.isfinite(force), axis=1)   # the first row: no load
    weight = drone.mass*float(np.linalg.norm(drone.g))
    mean = [mean_over(series.time[good], force[good, c], t0, t1)
            for c in (2, 0)]
    R = series.bodies[s.pitch_body].orientation
    pitch = np.degrees(np.arcsin(-R[:, 6]))
    ends = [np.interp(t, series.time, pitch) for t in (t0, t1)]
    return [float(mean[0]/weight - 1), float(mean[1]/weight),
            float(ends[1] - ends[0])/s.average]


def fly(s, problem, values, k, model):
    """Run k (or the Jacobian's run named k) with the values: flown,
    continued or read again; its residuals."""
    folder = os.path.join(s.dir, k)
    started = time.time()
    if not finished(folder, s):
        cmd = command(s, problem, values, folder, model)
        with open(folder + ".log", "a") as log:
            log.write("\n$ %s\n" % " ".join(cmd))
            log.flush()
            rc = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT,
                                 stdin=subprocess.DEVNULL)
        if rc != 0:
            raise StudyError("%s failed (exit %d): see %s.log"
                             % (" ".join(cmd), rc, folder))
    return Run(list(values), residuals(folder, s), folder,
               time.time() - started)


def scaled(s, r):
    return np.array([r[0], r[1], r[2]*s.force_tolerance/s.pitch_tolerance])


def qs_jacobian(s, problem):
    """d(scaled residuals)/d(values) of the QS model flown as the runs."""
    base = fly(s, problem, problem.start, "qs-base", "quasiSteady")
    columns = []
    for i, (lo, hi) in enumerate(problem.ranges):
        h = (hi - lo)*s.fd_step
        values = list(problem.start)
        values[i] += h
        moved = fly(s, problem, values, "qs-%d" % i, "quasiSteady")
        columns.append((scaled(s, moved.residuals)
                        - scaled(s, base.residuals))/h)
    return np.column_stack(columns)


def next_values(s, problem, run):
    """The Gauss-Newton step from the run, inside the ranges."""
    step = np.linalg.lstsq(problem.jacobian, -scaled(s, run.residuals),
                           rcond=None)[0]
    return [min(max(v + d, lo), hi) for v, d, (lo, hi) in
            zip(run.values, step, problem.ranges)]


def line(k, problem, run):
    return "cfd_trim: run %d: %s; F_z/W - 1 = %+.4f, F_x/W = %+.4f," \
        " pitch %+.3f deg a cycle (%.0f s)" % (
            k, ", ".join("%s %.6g" % nv for nv in zip(problem.names,
                                                      run.values)),
            run.residuals[0], run.residuals[1], run.residuals[2],
            run.seconds)


def cfd_trim(s, report=print):
    """The runs until converged or -maxRuns: the Problem with its runs."""
    os.makedirs(s.dir, exist_ok=True)
    problem = problem_of(s)
    problem.jacobian = qs_jacobian(s, problem)
    values = problem.start
    for k in range(s.max_runs):
        run = fly(s, problem, values, "run-%d" % k, s.model)
        problem.runs.append(run)
        report(line(k, problem, run))
        if run.converged(s):
            break
        values = next_values(s, problem, run)
    return problem


def summary(s, problem):
    last = problem.runs[-1]
    return {"cfd_trim_runs": len(problem.runs),
            "cfd_trim_converged": bool(last.converged(s)),
            "cfd_trim_force_residual_over_weight":
                max(abs(last.residuals[0]), abs(last.residuals[1])),
            "cfd_trim_pitch_change_deg_per_cycle": last.residuals[2],
            "cfd_trim_variables": dict(zip(problem.names, last.values))}


def plot(path, s, problem):
    from flapfoam.plots.backend import pyplot
    plt = pyplot()
    r = np.array([run.residuals for run in problem.runs])
    k = np.arange(len(r))
    fig, ax = plt.subplots(2, 1, figsize=(6, 5), sharex=True)
    ax[0].plot(k, r[:, 0], "o-", label="$F_z/W - 1$")
    ax[0].plot(k, r[:, 1], "s-", label="$F_x/W$")
    for a, tol in ((ax[0], s.force_tolerance), (ax[1], s.pitch_tolerance)):
        a.axhspan(-tol, tol, color="0.9")
        a.axhline(0, color="k", lw=0.5)
    ax[0].set_ylabel("mean force residual")
    ax[0].legend()
    ax[1].plot(k, r[:, 2], "d-", color="C2")
    ax[1].set_ylabel("pitch change [deg/cycle]")
    ax[1].set_xlabel("run")
    ax[1].set_xticks(k)
    fig.suptitle("Trim in %s: the last %d of %d cycles per run"
                 % ("CFD" if s.model == "cfd" else "the QS model",
                    s.average, s.cycles))
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def arguments(argv):
    parser = argparse.ArgumentParser(
        prog="flapfoam cfd_trim", description=__doc__.split("\n\n")[1].strip(),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    d = Settings(dir="")
    parser.add_argument("-dir", required=True)
    parser.add_argument("-case", default=d.case)
    parser.add_argument("-variant", default=d.variant)
    parser.add_argument("-level", default=d.level)
    parser.add_argument("-model", default=d.model,
                        choices=("cfd", "quasiSteady"))
    parser.add_argument("-pitchBody", dest="pitch_body", default=d.pitch_body)
    for name, kind in (("np", int), ("cycles", int), ("average", int),
                       ("maxRuns", int), ("forceTolerance", float),
                       ("pitchTolerance", float), ("fdStep", float)):
        dest = "".join("_" + c.lower() if c.isupper() else c for c in name)
        parser.add_argument("-" + name, dest=dest, type=kind,
                            default=getattr(d, dest))
    parser.add_argument("-start", default="", metavar="NAME=V,...")
    parser.add_argument("-o", metavar="PREFIX")
    parser.add_argument("-summary", metavar="FILE")
    args = parser.parse_args(argv)
    try:
        args.start = {n: float(v) for n, v in (
            w.split("=") for w in args.start.split(",") if w)}
    except ValueError:
        parser.error("-start %s: not allowed (ENTRY.KEY=VALUE,...)"
                     % args.start)
    for name in ("np", "cycles", "average", "max_runs"):
        if getattr(args, name) < 1:
            parser.error("-%s %d: not allowed (an integer >= 1)"
                         % (name, getattr(args, name)))
    for name in ("force_tolerance", "pitch_tolerance", "fd_step"):
        v = getattr(args, name)
        if not (v > 0 and math.isfinite(v)):
            parser.error("%s %g: not allowed (> 0)" % (name, v))
    if args.average > args.cycles:
        parser.error("-average %d: not allowed (<= -cycles %d)"
                     % (args.average, args.cycles))
    return args


def main(argv=None):
    args = arguments(argv)
    s = Settings(**{k: v for k, v in vars(args).items()
                    if k not in ("o", "summary")})
    s.dir = os.path.abspath(s.dir)
    s.case = os.path.abspath(s.case)
    try:
        problem = cfd_trim(s)
    except (StudyError, OSError, KeyError) as e:
        sys.exit("cfd_trim: %s" % e)
    keys = summary(s, problem)
    print("cfd_trim: %s after %d run(s): largest force residual %.4f of the"
          " weight, pitch %+.3f deg a cycle" % (
              "converged" if keys["cfd_trim_converged"] else "NOT converged",
              keys["cfd_trim_runs"],
              keys["cfd_trim_force_residual_over_weight"],
              keys["cfd_trim_pitch_change_deg_per_cycle"]))
    if args.o:
        with open(args.o + ".json", "w") as f:
            json.dump(dict(keys, names=problem.names,
                           jacobian=problem.jacobian.tolist(),
                           runs=[vars(r) for r in problem.runs]), f, indent=1)
        plot(args.o + ".png", s, problem)
    if args.summary:
        write_summary(args.summary, keys)
    if not keys["cfd_trim_converged"]:
        sys.exit(1)


if __name__ == "__main__":
    run_tool(main)
