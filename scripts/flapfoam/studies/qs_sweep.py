# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
A kinematics sweep of the quasi-steady (QS) model: rigidBodySimulate
-bodyLoad aerodynamics on a multibody dictionary (default: the single-wing
drone's constant/dynamicMeshDict.eABA) at every point of a grid of the
Wang kinematics (the imposedMotion entries of waveform flapping and
pitching) and the mass, from rest over N whole cycles.

    flapfoam qs_sweep -grid "flapAmplitude=1.0:1.5:10
        pitchAmplitude=0.5:1.0:10" [-dict FILE] [-cycles 5]
        [-stepsPerCycle 250] [-solver Newmark] [-nIter N] [-np 2]
        [-dir DIR] [-o PREFIX] [-map X,Y] [-hover PARAM] [-hoverTol 1e-6]
        [-massBody NAME] [-keep]

Grid: NAME=LO:HI:N (N values, LO and HI included), NAME=V1,V2,... or
NAME=V; parameters (the dictionary's value where not given):
    flapAmplitude, flapK, flapPhase     the flapping entry (rad, -, rad)
    pitchAmplitude, pitchK, pitchPhase  the pitching entry (rad, -, rad)
    frequency                           both entries [Hz]
    mass                                the mass of -massBody (default:
                                        the first aerodynamics entry's
                                        body, the drone for SW) [kg]
Each point runs cycles/frequency seconds with deltaT = 1/(frequency
stepsPerCycle), a row of joints.dat per step, with the integrator -solver
(default Newmark: second order here, its climb rate within 1e-5 of the
converged one at 250 steps per cycle, where symplectic is 1 % off) and
-nIter (default: the dictionary's), and gives (PREFIX.csv):
    meanClimbRate          (z(T) - z(0))/T, z the first free Pz joint [m/s]
    meanClimbAcceleration  (zDot(T) - zDot(0))/T [m/s^2]
    forceOverWeight        1 + meanClimbAcceleration/|g|: the mean vertical
                           force over the weight (1: hover; exact where Pz
                           is the root joint and the rest moves
                           periodically)
    meanDrift              (x(T) - x(0))/T, x the first free Px joint [m/s]
    meanPower              the prescribed joints' mean power (sum of the
                           power_<j> columns, trapezoidal mean) [W], and
                           meanPower_<j> per joint
    xEnd, zEnd             the final position [m]; seconds: the run's cost
PREFIX.png: heat-maps of the climb rate, drift and power over the -map
pair (default: the first two parameters of more than one value; the mean
over any other such parameter), or curves when one parameter varies.
-hover PARAM: for every combination of the other parameters, the value of
PARAM with zero meanClimbAcceleration (Brent's method between the grid's
values of PARAM where its sign changes): PREFIX-hover.csv.
numpy, matplotlib; scipy for -hover.
"""

import argparse
import itertools
import math
import os
import re
import shutil
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from flapfoam.io import run_series
from flapfoam.io.foam_dict import read_foam_dict, set_entry
from flapfoam.errors import run_tool
from flapfoam.paths import project_path
from flapfoam.studies import qs_case
from flapfoam.studies.qs_case import StudyError

# name: (imposedMotion waveform or None, key, allowed (lo, hi) open range)
PARAMETERS = {
    "flapAmplitude": ("flapping", "amplitude", (0.0, math.inf)),
    "flapK": ("flapping", "K", (0.0, 1.0)),
    "flapPhase": ("flapping", "phase", (-math.inf, math.inf)),
    "pitchAmplitude": ("pitching", "amplitude", (0.0, math.inf)),
    "pitchK": ("pitching", "K", (0.0, math.inf)),
    "pitchPhase": ("pitching", "phase", (-math.inf, math.inf)),
    "frequency": (None, "frequency", (0.0, math.inf)),
    "mass": (None, "mass", (0.0, math.inf)),
}

SOLVERS = ("Newmark", "symplectic", "CrankNicolson")

RESULTS = ("meanClimbRate", "meanClimbAcceleration", "forceOverWeight",
           "meanDrift", "meanPower")


class SweepError(StudyError):
    """Bad input: the message names the option, the value and what is
    allowed."""


def parse_values(name, spec, bounds):
    """The values of one grid entry NAME=SPEC, each in the open range
    bounds (lo, hi)."""
    try:
        if spec.count(":") == 2:
            lo, hi, n = spec.split(":")
            n = int(n)
            if n < 1:
                raise ValueError
            values = list(np.linspace(float(lo), float(hi), n))
        else:
            values = [float(v) for v in spec.split(",")]
    except ValueError:
        raise SweepError("-grid %s=%s: not allowed (LO:HI:N with N >= 1,"
                         " V1,V2,... or V; numbers)" % (name, spec))
    lo, hi = bounds
    for v in values:
        if not (math.isfinite(v) and lo < v < hi):
            raise SweepError("-grid %s=%s: value %r not allowed (%s < %s < %s)"
                             % (name, spec, v, lo, name, hi))
    return values


def parse_grid(text, bounds=None):
    """{name: [values]} of -grid "NAME=SPEC ..." (order kept); bounds:
    {NAME: (lo, hi)} of the allowed names (default: PARAMETERS')."""
    bounds = bounds or {n: p[2] for n, p in PARAMETERS.items()}
    grid = {}
    for word in text.split():
        name, eq, spec = word.partition("=")
        if name not in bounds or not eq:
            raise SweepError("-grid '%s': not allowed (NAME=SPEC, NAME one"
                             " of: %s)" % (word, ", ".join(bounds)))
        if name in grid:
            raise SweepError("-grid: %s given twice" % name)
        grid[name] = parse_values(name, spec, bounds[name])
    if not grid:
        raise SweepError("-grid '%s': not allowed (at least one NAME=SPEC)"
                         % text)
    return grid


class Model:
    """The multibody dictionary as a template: the swept entries replaced
    by placeholder words (foamDictionary -precision 17 -set), filled in per
    point; the solver and nIter set once."""

    def __init__(self, path, work_dir, solver=None, n_iter=None,
                 mass_body=None):
        if not os.path.isfile(path):
            raise SweepError("-dict %s: no such file" % path)
        d = read_foam_dict(path)
        self.prefix = "eABAMeshMotionCoeffs/" \
            if "eABAMeshMotionCoeffs" in d else ""
        coeffs = d.get("eABAMeshMotionCoeffs", d)
        self.entries = self._waveform_entries(path, coeffs)
        aero = [e for e in coeffs.get("aerodynamics", {}).values()
                if isinstance(e, dict)]
        if not aero:
            raise SweepError("-dict %s: no aerodynamics entry with a wing"
                             " (allowed: a multibody dictionary with"
                             " aerodynamics { NAME { type quasiSteady; ...}})"
                             % path)
        self.mass_body = mass_body or aero[0]["body"][0]
        if self.mass_body not in coeffs.get("bodies", {}):
            raise SweepError("-massBody %s: not allowed (a body of %s: %s)"
                             % (self.mass_body, path,
                                ", ".join(coeffs.get("bodies", {}))))
        self.g = abs(float(coeffs.get("g", ["(", "0", "0", "0", ")"])[3]))
        self.defaults = self._defaults(coeffs)
        self.template = os.path.join(work_dir, "dynamicMeshDict.template")
        shutil.copy(path, self.template)
        for name in PARAMETERS:
            for entry in self._paths(name):
                self._set(entry, "qsSweep_" + name)
        if solver:
            self._set("solver/type", solver)
        if n_iter:
            self._set("nIter", str(n_iter))
        with open(self.template) as f:
            self.text = f.read()

    @staticmethod
    def _waveform_entries(path, coeffs):
        entries = {}
        for name, e in coeffs.get("imposedMotion", {}).items():
            if isinstance(e, dict) and e.get("type") == ["wang"]:
                entries.setdefault(e.get("waveform", [""])[0], name)
        for waveform in ("flapping", "pitching"):
            if waveform not in entries:
                raise SweepError("-dict %s: no imposedMotion entry of type"
                                 " wang, waveform %s (allowed: a dictionary"
                                 " with both waveforms)" % (path, waveform))
        return entries

    def _paths(self, name):
        waveform, key, _ = PARAMETERS[name]
        if name == "mass":
            return ["bodies/%s/mass" % self.mass_body]
        waveforms = [waveform] if waveform else ["flapping", "pitching"]
        return ["imposedMotion/%s/%s" % (self.entries[w], key)
                for w in waveforms]

    def _defaults(self, coeffs):
        values = {}
        for name in PARAMETERS:
            path = self._paths(name)[0].split("/")
            entry = coeffs
            for key in path[:-1]:
                entry = entry[key]
            values[name] = float(entry.get(path[-1], ["0"])[0])
        return values

    def _set(self, entry, value):
        set_entry(self.template, self.prefix + entry, value)

    def write(self, path, values):
        """The dictionary of one point (values: {name: value}, the
        dictionary's own for the others)."""
        text = self.text
        for name in PARAMETERS:
            text = re.sub(r"\bqsSweep_%s\b" % name,
                          repr(float(values.get(name, self.defaults[name]))),
                          text)
        with open(path, "w") as f:
            f.write(text)


CONTROLDICT = """\
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application rigidBodySimulate;
startFrom startTime; startTime 0; stopAt endTime; endTime %r;
deltaT %r; writeControl timeStep; writeInterval 1;
writeFormat ascii; writePrecision 12; writeCompression off;
timeFormat general; timePrecision 12;
"""


def joint_map(log):
    """(heave, surge): the q indices of the first free Pz and Px joints in
    rigidBodySimulate's joint state map."""
    free = {}
    for j in qs_case.joint_map(log):
        if j.motion is None:
            free.setdefault(j.type, j.index)
    return free.get("Pz"), free.get("Px")


def point_results(data, names, heave, surge, g):
    """The sweep's results of one run's joints.dat (data, column names)."""
    col = {n: i for i, n in enumerate(names)}
    t = data[:, 0]
    T = t[-1] - t[0]
    z, z_dot, x = (data[:, col["%s_%d" % (kind, q)]] for kind, q in
                  (("q", heave), ("qDot", heave), ("q", surge)))
    rate, acceleration, drift = ((c[-1] - c[0])/T for c in (z, z_dot, x))
    row = {"meanClimbRate": rate, "meanClimbAcceleration": acceleration,
           "forceOverWeight": 1 + acceleration/g if g else math.nan,
           "meanDrift": drift, "meanPower": 0.0}
    for n in names:
        if n.startswith("power_"):
            p = data[:, col[n]]
            row["meanP" + n[1:]] = float(np.sum(0.5*(p[1:] + p[:-1])
                                                *np.diff(t))/T)
            row["meanPower"] += row["meanP" + n[1:]]
    row.update(xEnd=x[-1], zEnd=z[-1])
    return row


class Sweep:
    """Runs the points of a model (rigidBodySimulate -bodyLoad
    aerodynamics), each in its own case folder under workDir (removed
    after a successful run unless keep)."""

    def __init__(self, model, work_dir, cycles, steps_per_cycle, keep=False):
        self.model = model
        self.work_dir = work_dir
        self.cycles = cycles
        self.steps_per_cycle = steps_per_cycle
        self.keep = keep

    def run(self, name, values):
        """{results} of the point values ({name: value}); SweepError if
        rigidBodySimulate fails."""
        case = os.path.join(self.work_dir, name)
        shutil.rmtree(case, ignore_errors=True)
        os.makedirs(os.path.join(case, "constant"))
        os.makedirs(os.path.join(case, "system"))
        self.model.write(os.path.join(case, "constant", "dynamicMeshDict"),
                         values)
        f = values.get("frequency", self.model.defaults["frequency"])
        with open(os.path.join(case, "system", "controlDict"), "w") as out:
            out.write(CONTROLDICT % (self.cycles/f,
                                     1.0/(f*self.steps_per_cycle)))
        rc, seconds = qs_case.simulate(case, "log")
        with open(os.path.join(case, "log")) as log:
            text = log.read()
        heave, surge = joint_map(text)
        if rc != 0 or heave is None or surge is None:
            raise SweepError("point %s %s: rigidBodySimulate exit %d%s; see"
                             " %s/log" % (name, values, rc, "" if rc else
                                          " (no free Pz and Px joints)",
                                          case))
        names, data = run_series.read(case).joints_table()
        row = point_results(data, names, heave, surge, self.model.g)
        row["seconds"] = seconds
        if not self.keep:
            shutil.rmtree(case)
        return row

    def run_all(self, points, n_procs):
        """The rows (values and results) of a list of points, nProcs runs
        at a time."""
        def one(item):
            i, values = item
            row = dict(values)
            row.update(self.run("p%05d" % i, values))
            return row

        with ThreadPoolExecutor(max_workers=n_procs) as pool:
            return list(pool.map(one, enumerate(points)))


def grid_points(grid):
    """[{name: value}] of every combination, the last name fastest."""
    names = list(grid)
    return [dict(zip(names, v)) for v in itertools.product(*grid.values())]


class Hover:
    """The value of one parameter with zero mean climb acceleration, per
    combination of the others: Brent's method (scipy) between neighbouring
    grid values where the sweep's acceleration changes sign."""

    def __init__(self, sweep, grid, param, xtol):
        if param not in grid or len(grid[param]) < 2:
            raise SweepError("-hover %s: not allowed (a parameter of the"
                             " grid with at least 2 values: %s)" % (param,
                             ", ".join(n for n in grid if len(grid[n]) > 1)
                             or "none"))
        self.sweep, self.grid, self.param, self.xtol = sweep, grid, param, \
            xtol

    def find(self, others, rows, name):
        """The hover row of the combination others (rows: the sweep's rows
        of it, in the order of the grid's values of param)."""
        from scipy.optimize import brentq
        a = [r["meanClimbAcceleration"] for r in rows]
        values = sorted(self.grid[self.param])
        bracket = [i for i in range(len(a) - 1) if a[i]*a[i + 1] <= 0]
        row = dict(others)
        if not bracket:
            row.update({self.param: math.nan, "evaluations": 0,
                        "note": "no sign change: forceOverWeight %.4g .. "
                        "%.4g" % (rows[0]["forceOverWeight"],
                                  rows[-1]["forceOverWeight"])})
            return row
        runs = []

        def acceleration(v):
            point = dict(others, **{self.param: v})
            runs.append(self.sweep.run("%s-%d" % (name, len(runs)), point))
            return runs[-1]["meanClimbAcceleration"]

        i = bracket[0]
        row[self.param] = brentq(acceleration, values[i], values[i + 1],
                                 xtol=self.xtol)
        row["evaluations"] = len(runs)
        # the hover point's own run
        row.update(self.sweep.run(name, row))
        row["note"] = ""
        return row

    def table(self, rows, n_procs):
        """The hover rows of every combination of the other parameters."""
        others = [n for n in self.grid if n != self.param]
        combos = grid_points({n: self.grid[n] for n in others})

        def rows_of(c):
            return sorted((r for r in rows
                           if all(r[k] == c[k] for k in others)),
                          key=lambda r: r[self.param])

        with ThreadPoolExecutor(max_workers=n_procs) as pool:
            return list(pool.map(
                lambda ic: self.find(ic[1], rows_of(ic[1]),
                                     "hover%03d" % ic[0]),
                enumerate(combos)))


def write_table(path, rows, first):
    """A CSV of rows: the columns first, then the others in order of
    appearance."""
    columns = list(first)
    for r in rows:
        columns += [c for c in r if c not in columns]

    def text(v):
        return v if isinstance(v, str) else "%.10g" % v

    with open(path, "w") as f:
        f.write(",".join(columns) + "\n")
        for r in rows:
            f.write(",".join(text(r.get(c, math.nan)) for c in columns)
                    + "\n")


PLOTTED = (("meanClimbRate", "mean climb rate [m/s]", "RdBu_r"),
           ("meanDrift", "mean horizontal drift [m/s]", "RdBu_r"),
           ("meanPower", "mean power of the prescribed joints [W]",
            "viridis"))


def plot(path, rows, grid, pair, title):
    """Heat-maps of PLOTTED over the parameters pair (X, Y), the mean over
    any other varying parameter; curves when pair has one name."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(PLOTTED), figsize=(5*len(PLOTTED), 4))
    for ax, (key, label, cmap) in zip(axes, PLOTTED):
        xs = sorted(grid[pair[0]])
        if len(pair) == 1:
            ax.plot(xs, [np.mean([r[key] for r in rows if r[pair[0]] == x])
                         for x in xs], "o-")
            ax.set_xlabel(pair[0])
            ax.set_ylabel(label)
            ax.grid(True)
            continue
        ys = sorted(grid[pair[1]])
        z = np.array([[np.mean([r[key] for r in rows if r[pair[0]] == x
                                and r[pair[1]] == y]) for x in xs]
                      for y in ys])
        lim = np.nanmax(np.abs(z)) if cmap == "RdBu_r" else None
        mesh = ax.pcolormesh(edges(xs), edges(ys), z, cmap=cmap,
                             vmin=-lim if lim else None, vmax=lim,
                             shading="flat")
        if key == "meanClimbRate" and np.nanmin(z) < 0 < np.nanmax(z) \
                and min(z.shape) > 1:
            ax.contour(xs, ys, z, levels=[0], colors="k")
        fig.colorbar(mesh, ax=ax, label=label)
        ax.set_xlabel(pair[0])
        ax.set_ylabel(pair[1])
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def edges(values):
    """Cell edges around sorted values (their midpoints; half a step out at
    the ends, or +-0.5 of a single value)."""
    v = np.asarray(values, dtype=float)
    if len(v) == 1:
        return np.array([v[0] - 0.5, v[0] + 0.5])
    mid = 0.5*(v[1:] + v[:-1])
    return np.concatenate([[2*v[0] - mid[0]], mid, [2*v[-1] - mid[-1]]])


def map_pair(grid, text):
    """The plotted parameters: -map X,Y (or X), else the first two that
    vary (or the first one)."""
    varying = [n for n in grid if len(grid[n]) > 1] or list(grid)[:1]
    if text is None:
        return varying[:2]
    pair = text.split(",")
    if not 1 <= len(pair) <= 2 or any(p not in grid for p in pair) \
            or len(set(pair)) != len(pair):
        raise SweepError("-map %s: not allowed (X,Y or X: parameters of the"
                         " grid: %s)" % (text, ", ".join(grid)))
    return pair


def hover_line(param, r):
    """The report of one hover row."""
    if r["note"]:
        return "no hover %s in the grid's range (%s)" % (param, r["note"])
    return ("%s = %.9g: mean climb acceleration %.3g m/s^2, rate %.3g m/s,"
            " force/weight %.6f, mean power %.4g W (%d runs)"
            % (param, r[param], r["meanClimbAcceleration"],
               r["meanClimbRate"], r["forceOverWeight"], r["meanPower"],
               r["evaluations"]))


def arguments(argv):
    parser = argparse.ArgumentParser(
        prog="flapfoam qs_sweep", description=__doc__.split("\n\n")[0])
    default = project_path("cases", "singleWingDrone", "constant",
                           "dynamicMeshDict.eABA")
    parser.add_argument("-grid", required=True)
    parser.add_argument("-dict", default=default)
    parser.add_argument("-cycles", type=int, default=5)
    parser.add_argument("-stepsPerCycle", dest="steps_per_cycle", type=int,
                        default=250)
    parser.add_argument("-solver", choices=SOLVERS, default="Newmark")
    parser.add_argument("-nIter", dest="n_iter", type=int)
    parser.add_argument("-np", type=int, default=2)
    parser.add_argument("-dir", default="/tmp/flapFoam-qsSweep")
    parser.add_argument("-o", default="qsSweep")
    parser.add_argument("-map")
    parser.add_argument("-hover", metavar="PARAM")
    parser.add_argument("-hoverTol", dest="hover_tol", type=float,
                        default=1e-6,
                        help="tolerance on the hover value (default 1e-6)")
    parser.add_argument("-massBody", dest="mass_body",
                        help="the body of the parameter mass")
    parser.add_argument("-keep", action="store_true")
    args = parser.parse_args(argv)
    for option, v, least in (("cycles", args.cycles, 1),
                             ("stepsPerCycle", args.steps_per_cycle, 4),
                             ("np", args.np, 1), ("nIter", args.n_iter, 1)):
        if v is not None and v < least:
            parser.error("-%s %d: not allowed (an integer >= %d)"
                         % (option, v, least))
    if not args.hover_tol > 0:
        parser.error("-hoverTol %g: not allowed (> 0)" % args.hover_tol)
    return args


def main(argv=None):
    args = arguments(argv)
    try:
        grid = parse_grid(args.grid)
        pair = map_pair(grid, args.map)
        os.makedirs(args.dir, exist_ok=True)
        model = Model(args.dict, args.dir, args.solver, args.n_iter,
                      args.mass_body)
        sweep = Sweep(model, args.dir, args.cycles, args.steps_per_cycle,
                      args.keep)
        hover = Hover(sweep, grid, args.hover, args.hover_tol) \
            if args.hover else None
        start = time.time()
        rows = sweep.run_all(grid_points(grid), args.np)
        wall = time.time() - start
        write_table(args.o + ".csv", rows, list(grid) + list(RESULTS))
        print("qs_sweep: %d points (%d cycles, %d steps per cycle, %d at a"
              " time) in %.1f s wall, %.3f s per run: %s.csv"
              % (len(rows), args.cycles, args.steps_per_cycle, args.np, wall,
                 np.mean([r["seconds"] for r in rows]), args.o))
        plot(args.o + ".png", rows, grid, pair,
             "%s: %d points, %d cycles from rest" % (
                 os.path.basename(args.dict), len(rows), args.cycles))
        if hover:
            table = hover.table(rows, args.np)
            write_table(args.o + "-hover.csv", table,
                       list(grid) + list(RESULTS) + ["evaluations"])
            for r in table:
                print("qs_sweep: %s: %s" % (", ".join(
                    "%s %.6g" % (n, r[n]) for n in grid if n != args.hover)
                    or "hover", hover_line(args.hover, r)))
    except SweepError as e:
        sys.exit("qs_sweep: %s" % e)


if __name__ == "__main__":
    run_tool(main)
