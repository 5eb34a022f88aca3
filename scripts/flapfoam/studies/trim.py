# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Trim of a drone case on the quasi-steady (QS) model: the kinematic
parameters the case names as trim variables and the free joints' state at
the start of a flapping cycle such that one cycle of the full multibody
dynamics (rigidBodySimulate, not cycle-averaged) comes back to the same
state with the target's mean velocity: a periodic flight.

    flapfoam trim [-case cases/bodyWingDrone] [-variant V ...]
        [-edits FILE] [-climb VZ] [-forward VX] [-deltaT DT]
        [-trimDict FILE] [-tolerance 1e-8] [-maxIterations 20]
        [-fdStep 1e-6] [-np 1] [-write NAME] [-o PREFIX] [-summary FILE]
        [-dir DIR] [-keep]

Target: the mean velocity over a cycle of the free translations, -climb
along z and -forward along x [m/s] (both 0: hover).  Variables: the case's
system/trimDict (or -trimDict FILE),

    variables
    {
        flapping.amplitude  (0.9 1.5);     // ENTRY.KEY  (min max)
        flapping.offset     (-0.4 0.4);
    }

ENTRY an imposedMotion entry of the case's dictionary (with the variants
and -edits FILE: dictionary edits in a variant's format, e.g. a trim's
PREFIX.variant),
KEY one of the keys its type lets a trim vary (wang: amplitude offset phase
K; harmonic: amplitude offset phase; never the frequency: every trial has
the same cycle and time step); a trial never leaves the range.  Unknowns:
the variables and the state (flapfoam.studies.cycle_map: free rotations'
angles, every free joint's velocity; the free translations start at 0).
Residuals, in the map's scales: the state after one cycle minus the state
at its start, and the free translations' mean velocity minus the target.
Newton (Gauss-Newton, minimum-norm or least-squares steps where the
numbers of unknowns and residuals differ) with a forward-difference
Jacobian (step -fdStep in the scaled unknowns), the step halved while the
residual grows, until the largest scaled residual is below -tolerance.
A variable held at the end of its range for 3 iterations stops the trim:
the target is out of reach; the target component the variable moves most
is then trimmed at the variable's min and max (the variable fixed there,
that component free), and the range between is printed.

Prints the iterations, the trial runs and the time; the trimmed values;
the residuals: the state mismatch after a cycle (scaled, and per component
in SI) and the cycle-mean aerodynamic force over the weight along each
free translation (from a run with the case's flight data).  -write NAME:
the case variant CASE/variants/NAME (the given variants' and -edits'
lines, then the variables and q, qDot of the trimmed state), flown by
Allrun -model quasiSteady -variant NAME.  -o PREFIX: PREFIX.json (the
result), PREFIX.variant (the same lines: flapfoam floquet -edits
PREFIX.variant analyses the trim without a variant in the case) and
PREFIX.png (the convergence); -summary FILE: the trim's keys merged into
FILE (a results folder's summary.json).  numpy, matplotlib.
"""

import argparse
import copy
import json
import math
import os
import re
import shutil
import sys
import textwrap
import time
from dataclasses import dataclass, field

import numpy as np

from flapfoam.errors import run_tool
from flapfoam.io.foam_dict import read_foam_dict
from flapfoam.paths import project_path
from flapfoam.studies.cycle_map import (COEFFS, CycleMap, MapSettings,
                                        cycle_mean_loads, read_edits)
from flapfoam.studies.qs_case import (StudyError, check_ranges, linked,
                                       write_summary)

AXES = {"x": "forward", "z": "climb"}

# the trim's keys of the results' summary.json (trim.json has them all)
SUMMARY_KEYS = ("trim_residual_state", "trim_residual_force_over_weight",
                "trim_target_mean_velocity_m_per_s", "trim_variables",
                "trim_iterations", "trim_runs", "trim_seconds",
                "trim_aerodynamics")


@dataclass
class TrimSettings:
    """The trim's case (MapSettings), target {axis: mean velocity [m/s]},
    variables file (None: the case's system/trimDict), tolerance on the
    largest scaled residual, iteration limit, finite-difference step
    (scaled) and the iterations a variable may stay at a bound."""
    map: MapSettings
    target: dict = field(default_factory=dict)
    trim_dict: str = None
    tolerance: float = 1e-8
    max_iterations: int = 20
    fd_step: float = 1e-6
    bound_iterations: int = 3


def read_trim_dict(path):
    """{ENTRY.KEY: (min, max)} of a trimDict (StudyError for an unknown
    entry or a bad range)."""
    if not os.path.isfile(path):
        raise StudyError("%s: no trimDict (allowed: a file with variables"
                         " { ENTRY.KEY (min max); ... })" % path)
    d = read_foam_dict(path)
    for key in d:
        if key not in ("FoamFile", "variables"):
            raise StudyError("%s: unknown entry '%s' (allowed: variables)"
                             % (path, key))
    variables = d.get("variables")
    if not isinstance(variables, dict) or not variables:
        raise StudyError("%s: no variables { ENTRY.KEY (min max); ... }"
                         % path)
    ranges = {}
    for name, value in variables.items():
        try:
            lo, hi = (float(v) for v in value if v not in "()")
        except (TypeError, ValueError):
            lo = hi = math.nan
        if not lo < hi:
            raise StudyError("%s: variables/%s %s: not allowed (a range"
                             " (min max), min < max)" % (path, name,
                                                         " ".join(value)))
        ranges[name] = (lo, hi)
    return ranges


class Problem:
    """The trim's full vector z = (variables, state at the cycle start,
    target mean velocities), its scales and bounds, which of its entries
    are unknown, and the residuals of a trial."""

    def __init__(self, cycle_map, ranges, target):
        self.map = cycle_map
        layout = cycle_map.layout
        self.k = len(ranges)
        self.n = len(layout.names)
        self.axes = [j.type[1] for j in layout.translations]
        for axis in target:
            if axis not in self.axes:
                raise StudyError("-%s: not allowed (no free translation"
                                 " along %s; free: %s)" % (AXES[axis], axis,
                                                           " ".join(
                                                               self.axes)))
        self.lower = np.array([r[0] for r in ranges.values()] +
                              [-np.inf]*(self.n + len(self.axes)))
        self.upper = np.array([r[1] for r in ranges.values()] +
                              [np.inf]*(self.n + len(self.axes)))
        self.scales = np.concatenate([np.diff(list(ranges.values())).ravel(),
                                      layout.scales,
                                      [layout.velocity_scale]*len(self.axes)])
        self.names = list(ranges) + layout.names + \
            ["mean u_%s" % a for a in self.axes]
        self.z0 = np.concatenate([cycle_map.values,
                                  cycle_map.initial_state(),
                                  [target.get(a, 0.0) for a in self.axes]])
        self.unknown = list(range(self.k + self.n))
        self.residual_names = ["%s(T) - %s(0)" % (n, n)
                               for n in layout.names] + \
            ["mean u_%s - target" % a for a in self.axes]
        for name, (lo, hi), v in zip(ranges, ranges.values(), self.z0):
            if not lo <= v <= hi:
                raise StudyError("trim variable %s: the case's value %g is"
                                 " outside its range (%g %g)" % (name, v,
                                                                 lo, hi))

    def split(self, z):
        return z[:self.k], z[self.k:self.k + self.n], z[self.k + self.n:]

    def residual(self, z, flight):
        """The scaled residuals of a one-cycle flight from z."""
        _, x0, target = self.split(z)
        layout = self.map.layout
        mean = self.map.mean_velocity(flight)[0]
        return np.concatenate([(flight.states[1] - x0)/layout.scales,
                               (mean - target)/layout.velocity_scale])

    def flights(self, zs):
        """One-cycle flights of the vectors zs."""
        return self.map.run_all([self.split(z)[:2] for z in zs])


@dataclass
class Iteration:
    """One Newton iteration: z, the residuals, the runs so far."""
    z: np.ndarray
    r: np.ndarray
    runs: int
    seconds: float


class Newton:
    """Newton on a Problem's unknowns (Gauss-Newton where the numbers
    differ), forward-difference Jacobian, halving, bounds."""

    def __init__(self, problem, settings, report=None):
        self.p = problem
        self.s = settings
        self.report = report or (lambda line: None)
        self.runs = 0
        self.start = time.time()

    def evaluate(self, zs):
        flights = self.p.flights(zs)
        self.runs += len(zs)
        return [self.p.residual(z, f) for z, f in zip(zs, flights)]

    def jacobian(self, z, r):
        """Columns d r / d(z_j/scale_j) of the unknowns; a target entry's
        column is analytic (no run)."""
        columns, zs = {}, []
        for j in self.p.unknown:
            if j >= self.p.k + self.p.n:
                e = np.zeros(len(r))
                e[self.p.n + j - self.p.k - self.p.n] = -1.0
                columns[j] = e
                continue
            h = self.s.fd_step*self.p.scales[j]
            if z[j] + h > self.p.upper[j]:
                h = -h
            zj = z.copy()
            zj[j] += h
            zs.append((j, h, zj))
        for (j, h, _), rj in zip(zs, self.evaluate([a[2] for a in zs])):
            columns[j] = (rj - r)*self.p.scales[j]/h
        return np.column_stack([columns[j] for j in self.p.unknown])

    def step(self, z, r, J):
        """The next z and its residuals: the Newton step, within bounds,
        halved (up to 5 times) while the residual grows."""
        u = self.p.unknown
        dz = np.linalg.lstsq(J, -r, rcond=None)[0]*self.p.scales[u]
        for _ in range(6):
            zn = z.copy()
            zn[u] = np.clip(z[u] + dz, self.p.lower[u], self.p.upper[u])
            rn = self.evaluate([zn])[0]
            if np.linalg.norm(rn) < np.linalg.norm(r):
                break
            dz = 0.5*dz
        return zn, rn

    def line(self, history):
        """The report of the last iteration."""
        it, p = history[-1], self.p
        free = [j for j in p.unknown if j < p.k or j >= p.k + p.n]
        return ("iteration %d: largest scaled residual %.3e (%s); %s; %d"
                " runs, %.1f s" % (len(history) - 1, np.max(abs(it.r)),
                                   p.residual_names[int(np.argmax(abs(it.r)))],
                                   ", ".join("%s %.8g" % (p.names[j], it.z[j])
                                             for j in free), it.runs,
                                   it.seconds))

    def solve(self, z):
        """The Iterations from z until the largest |residual| is below the
        tolerance; StudyError naming a variable held at a bound (with its
        index: .bound) or the iteration limit."""
        r = self.evaluate([z])[0]
        history = [Iteration(z, r, self.runs, time.time() - self.start)]
        self.report(self.line(history))
        held = {}
        while np.max(abs(r)) >= self.s.tolerance:
            if len(history) > self.s.max_iterations:
                raise StudyError("no trim in %d iterations: largest scaled"
                                 " residual %.3g (%s)" % (
                                     self.s.max_iterations, np.max(abs(r)),
                                     self.p.residual_names[
                                         int(np.argmax(abs(r)))]))
            J = self.jacobian(z, r)
            z, r = self.step(z, r, J)
            history.append(Iteration(z, r, self.runs,
                                     time.time() - self.start))
            self.report(self.line(history))
            for j in [i for i in self.p.unknown if i < self.p.k]:
                at = z[j] in (self.p.lower[j], self.p.upper[j])
                held[j] = held.get(j, 0) + 1 if at else 0
                if held[j] >= self.s.bound_iterations:
                    raise BoundError(j, J, history)
        return history


class BoundError(StudyError):
    """A trim variable held at a bound: the target is out of reach."""

    def __init__(self, index, jacobian, history):
        StudyError.__init__(self, "variable %d at a bound" % index)
        self.index, self.jacobian, self.history = index, jacobian, history


def reachable(problem, settings, error):
    """The message of a target out of reach: the target component the
    held variable moves most, trimmed at the variable's min and max (the
    variable fixed there, that component free)."""
    p, j = problem, error.index
    rows = np.arange(p.n, p.n + len(p.axes))
    if not len(rows):
        return "%s stays at the end of its range: no trim" % p.names[j]
    row = rows[int(np.argmax(abs(error.jacobian[rows, j])))]
    axis, target = p.axes[row - p.n], p.z0[p.k + row]
    found = []
    for bound in (p.lower[j], p.upper[j]):
        q = copy.copy(p)
        q.unknown = [i for i in p.unknown if i != j] + [p.k + row]
        z = error.history[-1].z.copy()
        z[j] = bound
        try:
            z = Newton(q, settings).solve(z)[-1].z
            found.append("%.6g m/s at %s = %g" % (z[p.k + row], p.names[j],
                                                  bound))
        except StudyError as e:
            found.append("no trim at %s = %g (%s)" % (p.names[j], bound, e))
    return ("the target mean u_%s = %g m/s is out of reach: %s stays at the"
            " end of its range (%g %g) in the trimDict; trimmed with it at"
            " the range's ends, the mean u_%s is %s: the reachable range"
            " lies between (a wider range in the trimDict, or another"
            " variable, reaches further)" % (
                axis, target, p.names[j], p.lower[j], p.upper[j], axis,
                " and ".join(found)))


@dataclass
class TrimResult:
    """A trim: the Problem, its Iterations, the cycle-mean aerodynamic
    force over the weight {axis: value} of the trimmed cycle."""
    problem: Problem
    history: list
    force_over_weight: dict

    @property
    def z(self):
        return self.history[-1].z

    def state_mismatch(self):
        """{state: x(T) - x(0)} in SI units."""
        p = self.problem
        r = self.history[-1].r[:p.n]*p.map.layout.scales
        return dict(zip(p.map.layout.names, r))

    def summary(self):
        """The trim's keys of the results' summary.json."""
        p, last = self.problem, self.history[-1]
        values, x0, target = p.split(self.z)
        q, q_dot = p.map.layout.to_q(x0)
        loads = self.force_over_weight
        return {
            "trim_target_mean_velocity_m_per_s": dict(zip(p.axes,
                                                          target.tolist())),
            "trim_variables": dict(zip(p.names[:p.k], values.tolist())),
            "trim_initial_q": q.tolist(),
            "trim_initial_q_dot": q_dot.tolist(),
            "trim_residual_state": float(np.max(abs(last.r[:p.n]))),
            "trim_residual_state_si": self.state_mismatch(),
            "trim_residual_mean_velocity_m_per_s": dict(zip(
                p.axes, (last.r[p.n:]*p.map.layout.velocity_scale).tolist())),
            "trim_mean_force_over_weight": loads,
            "trim_residual_force_over_weight": max(
                abs(v - (1.0 if a == "z" else 0.0)) for a, v in
                loads.items()) if loads else None,
            "trim_iterations": len(self.history) - 1,
            "trim_runs": last.runs,
            "trim_seconds": round(last.seconds, 2),
            "trim_delta_t_s": p.map.delta_t,
            "trim_period_s": p.map.period,
            "trim_aerodynamics": p.map.aerodynamics(),
        }


def trim(settings, report=print):
    """The TrimResult of the settings, each iteration reported by
    report(line); StudyError if there is none (the reachable range in the
    message where a variable runs out)."""
    cycle_map = CycleMap(settings.map)
    path = settings.trim_dict or os.path.join(cycle_map.folder, "system",
                                              "trimDict")
    ranges = read_trim_dict(path)
    cycle_map.prepare(list(ranges))
    problem = Problem(cycle_map, ranges, settings.target)
    try:
        history = Newton(problem, settings, report).solve(problem.z0)
    except BoundError as e:
        raise StudyError(reachable(problem, settings, e))
    values, x0, _ = problem.split(history[-1].z)
    flight = cycle_map.run(values, x0, 1, flight_data=True)
    loads = cycle_mean_loads(flight.folder, cycle_map.layout,
                             cycle_map.weight)
    if not settings.map.keep:
        shutil.rmtree(flight.folder)
    return TrimResult(problem, history, loads)


def variant_lines(result, settings, header):
    """The lines of a case variant that flies the trim: header comments,
    the given variants' edits (those the trim sets again left out), the
    variables and the state's q and qDot."""
    p = result.problem
    values, x0, _ = p.split(result.z)
    q, q_dot = p.map.layout.to_q(x0)
    mesh_dict = "constant/dynamicMeshDict"
    values_of = {"%s/imposedMotion/%s" % (COEFFS, n.replace(".", "/")):
                 "%r" % (sign*float(v))
                 for group, v in zip(p.names[:p.k], values)
                 for n, sign in linked(group)}
    values_of.update((COEFFS + "/" + k, "(%s)" % " ".join(
        "%r" % float(a) for a in v)) for k, v in (("q", q), ("qDot", q_dot)))
    own = list(values_of)
    lines = ["# " + h for h in header]
    lines += ["%s %s %s" % e for e in settings.map.edit_lines()
              if not (e[0] == mesh_dict and e[1] in own)]
    lines += ["%s %s %s" % (mesh_dict, e, v) for e, v in values_of.items()]
    return lines


def header_lines(result, command):
    """The variant's comment: what it is, how it was made, its residuals,
    the aerodynamics it was trimmed with (lines of at most 76 columns)."""
    s = result.summary()
    target = ", ".join("mean u_%s %g m/s" % a for a in
                       s["trim_target_mean_velocity_m_per_s"].items())
    text = ("A periodic flight of the quasi-steady model (target %s;"
            " deltaT %g s, cycle %g s): the trim variables and the free"
            " joints' state at t = 0 (q, qDot in q index order; the free"
            " translations at 0, the prescribed joints set by their"
            " motions).  After one cycle the state comes back within %.2g"
            " (scaled: rad, rad per cycle, g T); the cycle-mean aerodynamic"
            " force over the weight: %s.  Trimmed with the aerodynamics"
            " entry %s: after a change of the case's dictionary, trim again"
            " (the same command).  Written by flapfoam trim: rerun it rather"
            " than edit." % (
                target, s["trim_delta_t_s"], s["trim_period_s"],
                s["trim_residual_state"], ", ".join(
                    "%s %.9f" % a for a in
                    s["trim_mean_force_over_weight"].items()),
                "; ".join("%s: %s" % (w, " ".join("%s %.8g" % a
                                                  for a in c.items()))
                          for w, c in s["trim_aerodynamics"].items())))
    return ["Made by", "    " + command] + textwrap.wrap(text, 76)


def plot_convergence(path, result, tolerance):
    """The largest scaled residual (the tolerance dashed) and the
    unknowns' distance to the trim per iteration."""
    from flapfoam.plots.backend import pyplot
    plt = pyplot()
    p, history = result.problem, result.history
    its = np.arange(len(history))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    axes[0].semilogy(its, [np.max(abs(h.r)) for h in history], "o-")
    axes[0].axhline(tolerance, color="k", lw=0.8, ls="--")
    axes[0].set_xlabel("Newton iteration")
    axes[0].set_ylabel("largest scaled residual")
    for j in p.unknown:
        v = abs(np.array([h.z[j] for h in history]) - history[-1].z[j])
        axes[1].semilogy(its[:-1], v[:-1]/p.scales[j], "o-",
                         label=p.names[j])
    axes[1].set_xlabel("Newton iteration")
    axes[1].set_ylabel("|unknown - trimmed| / scale")
    axes[1].legend(fontsize=7)
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.set_xticks(its)
    s = result.summary()
    fig.suptitle("trim: %d iterations, %d one-cycle runs, %.1f s; state"
                 " residual %.2g, force/weight residual %.2g"
                 % (s["trim_iterations"], s["trim_runs"], s["trim_seconds"],
                    s["trim_residual_state"],
                    s["trim_residual_force_over_weight"]), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def arguments(argv):
    parser = argparse.ArgumentParser(
        prog="flapfoam trim", description=__doc__.split("\n\n")[1])
    parser.add_argument("-case", default=project_path("cases",
                                                      "bodyWingDrone"))
    parser.add_argument("-variant", action="append", default=[])
    parser.add_argument("-edits", metavar="FILE")
    parser.add_argument("-climb", type=float, help="mean u_z [m/s]")
    parser.add_argument("-forward", type=float, help="mean u_x [m/s]")
    parser.add_argument("-deltaT", dest="delta_t", type=float)
    parser.add_argument("-trimDict", dest="trim_dict")
    parser.add_argument("-tolerance", type=float, default=1e-8)
    parser.add_argument("-maxIterations", dest="max_iterations", type=int,
                        default=20)
    parser.add_argument("-fdStep", dest="fd_step", type=float, default=1e-6)
    parser.add_argument("-np", type=int, default=1)
    parser.add_argument("-write", metavar="NAME")
    parser.add_argument("-o", metavar="PREFIX")
    parser.add_argument("-summary", metavar="FILE")
    parser.add_argument("-dir", default="/tmp/flapFoam-trim")
    parser.add_argument("-keep", action="store_true")
    args = parser.parse_args(argv)
    check_ranges(parser, args, ("tolerance", "fd_step", "delta_t"), ("max_iterations", "np"))
    if args.write and not re.fullmatch(r"[A-Za-z0-9_.+-]+", args.write):
        parser.error("-write %s: not allowed (a variant name: letters,"
                     " digits, _ . + -)" % args.write)
    return args


def settings_of(args):
    target = {a: getattr(args, o) for a, o in AXES.items()
              if getattr(args, o) is not None}
    return TrimSettings(
        MapSettings(os.path.abspath(args.case), args.variant, args.delta_t,
                    os.path.abspath(args.dir), args.np, args.keep,
                    read_edits(args.edits) if args.edits else []),
        target, args.trim_dict, args.tolerance, args.max_iterations,
        args.fd_step)


def report_result(result):
    s = result.summary()
    print("trim: trimmed in %d iterations (%d one-cycle runs, %.1f s)"
          % (s["trim_iterations"], s["trim_runs"], s["trim_seconds"]))
    print("trim: " + ", ".join("%s = %.10g" % a
                                for a in s["trim_variables"].items()))
    print("trim: initial q = %s, qDot = %s" % (
        " ".join("%.9g" % v for v in s["trim_initial_q"]),
        " ".join("%.9g" % v for v in s["trim_initial_q_dot"])))
    print("trim: state mismatch after a cycle: %.3g scaled; %s" % (
        s["trim_residual_state"], ", ".join(
            "%s %.3g" % a for a in s["trim_residual_state_si"].items())))
    print("trim: cycle-mean aerodynamic force over the weight: %s" % (
        ", ".join("%s %.9f" % a for a in
                  s["trim_mean_force_over_weight"].items())))


def write_outputs(args, result, settings, command):
    """The variant (-write), PREFIX.json, .variant, .png (-o) and the
    summary's keys (-summary)."""
    lines = variant_lines(result, settings, header_lines(result, command))
    paths = []
    if args.write:
        paths.append(os.path.join(settings.map.case, "variants", args.write))
    if args.o:
        os.makedirs(os.path.dirname(os.path.abspath(args.o)), exist_ok=True)
        paths.append(args.o + ".variant")
        with open(args.o + ".json", "w") as f:
            json.dump(dict(result.summary(), trim_command=command), f,
                      indent=1)
        plot_convergence(args.o + ".png", result, settings.tolerance)
        print("trim: wrote %s.json, %s.png" % (args.o, args.o))
    for path in paths:
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        print("trim: wrote %s" % path)
    if args.summary:
        write_summary(args.summary, {k: v for k, v in result.summary().items()
                                     if k in SUMMARY_KEYS})
        print("trim: wrote the trim's keys into %s" % args.summary)


def main(argv=None):
    args = arguments(argv)
    try:
        settings = settings_of(args)
        result = trim(settings, lambda line: print("trim: " + line,
                                                   flush=True))
        report_result(result)
        command = "flapfoam trim " + " ".join(argv if argv is not None
                                              else sys.argv[1:])
        write_outputs(args, result, settings, command)
    except StudyError as e:
        sys.exit("trim: %s" % e)


if __name__ == "__main__":
    run_tool(main)
