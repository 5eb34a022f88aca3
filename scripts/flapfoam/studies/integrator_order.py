# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The observed order in deltaT of the multibody integrators (eABASolvers:
Newmark, symplectic, CrankNicolson; nIter absent, 1 and 3) on three
systems, each in rigidBodySimulate against an independent reference:

    doublePendulum   cases/doublePendulum (the paper's: joint 0 driven,
                     joint 1 free, from rest), flapfoam.models.chain_reference;
    threeLink        applications/test/integratorOrder/threeLink (free
                     root, prescribed middle, free tip, started away from
                     rest), flapfoam.models.chain_reference;
    singleWingDrone  cases/singleWingDrone's multibody dictionary with its
                     quasi-steady wings (-bodyLoad aerodynamics), one
                     cycle from rest, flapfoam.models.quasi_steady;
    singleWingDroneStaggered  the same with -staggeredLoads: the loads once
                     a step at the state of its start, as the overset
                     solver takes the flow's load (expected: first order).

Each combination runs at deltaT, deltaT/2 and deltaT/4; its error is the
largest difference from the reference over the written rows: of the
links' absolute angles [rad] (pendulums), of x and z [m] (drone).  The
observed orders are log2 of the ratios of successive errors; a combination
passes if both are at least 1.8 (or the errors are at round-off) and, on
the pendulums, its error at deltaT 1e-4 is below 2e-5 rad; on the
staggered drone if both are within 0.8-1.2.

    flapfoam integrator_order [-systems ...] [-solvers ...]
        [-nIter ...] [-dir DIR] [-jobs J] [-out TABLE.md]

prints one PASS or FAIL line a combination and the table (also to -out);
exit status 1 if one fails.
"""

import argparse
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
import functools
import math
import os
import shutil
import subprocess
import sys

import numpy as np

from flapfoam.models.chain_reference import Chain, Harmonic
from flapfoam.io.foam_dict import multibody_coeffs, read_state, set_entry
from flapfoam.models.quasi_steady import SingleWingDrone
from flapfoam.io import run_series
from flapfoam.errors import run_tool
from flapfoam.paths import project_dir

SOLVERS = ("Newmark", "symplectic", "CrankNicolson")
NITERS = ("default", "1", "3")
MIN_ORDER = 1.8
FIRST_ORDER = 0.8
ROUND_OFF = 1e-11
PENDULUM_LIMIT = 2e-5
CONTROL = """FoamFile { version 2.0; format ascii; class dictionary;
    object controlDict; }
application rigidBodySimulate;
startFrom startTime; startTime 0; stopAt endTime; endTime %(end)r;
deltaT %(dt)r; writeControl runTime; writeInterval %(write)r;
writeFormat ascii; writePrecision 17; writeCompression off;
timeFormat general; timePrecision 10; runTimeModifiable false;
"""


@dataclass(frozen=True)
class System:
    """One test system: where its multibody dictionary is, how it runs."""
    name: str
    case: str           # folder under the project with constant/<dict>
    dict_name: str      # the dictionary's file name in constant/
    coeffs: str         # the entries' prefix in it ("" or "X/")
    end_time: float
    delta_t: float      # the largest of the three
    write: float        # the rows' interval
    options: tuple = ()
    limit: float = 0.0  # error limit at delta_t (0: none)
    unit: str = "rad"
    order: int = 2      # the expected order


SYSTEMS = {
    s.name: s for s in (
        System("doublePendulum", "cases/doublePendulum", "dynamicMeshDict",
               "", 1.0, 1e-4, 1e-3, limit=PENDULUM_LIMIT),
        System("threeLink", "applications/test/integratorOrder/threeLink",
               "dynamicMeshDict", "", 1.0, 1e-4, 1e-3,
               limit=PENDULUM_LIMIT),
        System("singleWingDrone", "cases/singleWingDrone",
               "dynamicMeshDict.eABA", "eABAMeshMotionCoeffs/", 0.05, 1e-4,
               1e-3, options=("-bodyLoad", "aerodynamics"), unit="m"),
        System("singleWingDroneStaggered", "cases/singleWingDrone",
               "dynamicMeshDict.eABA", "eABAMeshMotionCoeffs/", 0.05, 1e-4,
               1e-3, options=("-bodyLoad", "aerodynamics",
                              "-staggeredLoads"), unit="m", order=1),
    )
}


@dataclass(frozen=True)
class Run:
    """One rigidBodySimulate run of a system."""
    system: System
    solver: str
    n_iter: str         # "default": no nIter entry
    delta_t: float
    root: str

    @property
    def path(self):
        return os.path.join(self.root, "%s-%s-nIter%s-dt%g" % (
            self.system.name, self.solver, self.n_iter, self.delta_t))


def set_up(run):
    """The run's case: the system's dictionary with the integrator set,
    its initial state if it has one, a controlDict."""
    src = os.path.join(project_dir(), run.system.case)
    if os.path.isdir(run.path):
        shutil.rmtree(run.path)
    os.makedirs(os.path.join(run.path, "constant"))
    os.makedirs(os.path.join(run.path, "system"))
    mesh_dict = os.path.join(run.path, "constant", "dynamicMeshDict")
    shutil.copy(os.path.join(src, "constant", run.system.dict_name),
                mesh_dict)
    state = os.path.join(src, "0", "uniform", "rigidBodyMotionState")
    if os.path.isfile(state):
        os.makedirs(os.path.join(run.path, "0", "uniform"))
        shutil.copy(state, os.path.join(run.path, "0", "uniform"))
    prefix = run.system.coeffs
    set_entry(mesh_dict, prefix + "solver/type", run.solver)
    set_entry(mesh_dict, prefix + "nIter",
                    None if run.n_iter == "default" else run.n_iter)
    with open(os.path.join(run.path, "system", "controlDict"), "w") as f:
        f.write(CONTROL % {"end": run.system.end_time, "dt": run.delta_t,
                           "write": run.system.write})


def simulate(run):
    """Set up and run; the run's folder."""
    set_up(run)
    with open(os.path.join(run.path, "log"), "w") as log:
        rc = subprocess.run(["rigidBodySimulate"] + list(run.system.options),
                            cwd=run.path, stdout=log,
                            stderr=subprocess.STDOUT).returncode
    if rc != 0:
        raise RuntimeError("rigidBodySimulate exit %d (see %s/log)"
                           % (rc, run.path))
    return run.path


def chain_of(system):
    """The Lagrangian chain of a pendulum system and its initial q, qDot,
    read from its dictionary and state file."""
    case = os.path.join(project_dir(), system.case)
    coeffs = multibody_coeffs(os.path.join(case, "constant",
                                          system.dict_name))
    bodies = [b for b in coeffs["bodies"].values() if isinstance(b, dict)]
    lengths = [-float(b["centreOfMass"][-2]) for b in bodies]
    for j, b in enumerate(bodies):
        joint_at = -float(b["transform"][-2])
        if abs(joint_at - (lengths[j - 1] if j else 0.0)) > 1e-15:
            raise ValueError("%s: body %d's joint at %g, not at the end of"
                             " its parent's rod: not a chain_reference chain"
                             % (system.case, j, joint_at))
    masses = [float(b["mass"][0]) for b in bodies]
    prescribed = {}
    for entry in coeffs["imposedMotion"].values():
        if isinstance(entry, dict):
            prescribed[int(entry["joint"][0])] = Harmonic(
                *(float(entry[k][0]) for k in
                  ("amplitude", "frequency", "phase", "offset")))
    q0, q_dot0 = np.zeros(len(bodies)), np.zeros(len(bodies))
    state = os.path.join(case, "0", "uniform", "rigidBodyMotionState")
    if os.path.isfile(state):
        s = read_state(state)
        q0, q_dot0 = np.asarray(s["q"], float), np.asarray(s["qDot"], float)
    g = -float(coeffs["g"][-2])
    return Chain(lengths, masses, g=g, prescribed=prescribed), q0, q_dot0


@functools.lru_cache(maxsize=None)
def reference(system):
    """The reference at the rows' times (every system.write from 0):
    (times, values), the values the links' absolute angles (pendulums, a
    column a link) or x, z (drone)."""
    n = int(round(system.end_time/system.write))
    times = np.linspace(0, n*system.write, n + 1)
    if system.unit == "rad":
        chain, q0, q_dot0 = chain_of(system)
        q, _ = chain.solve(q0, q_dot0, times)
        return times, np.cumsum(q, axis=1)
    coeffs = multibody_coeffs(os.path.join(project_dir(), system.case,
                                          "constant", system.dict_name))
    ref = SingleWingDrone(coeffs).fly(system.end_time, system.write)
    return ref[:, 0], ref[:, [1, 2]]


def observed(system, case):
    """The run's quantities in the reference's columns, from its joints.dat
    (rows at the write times): the links' absolute angles (q_j summed
    along the chain), or the drone's x (q_1, its Px joint) and z (q_0,
    Pz)."""
    rows = run_series.read(case, tables="rigidBodySimulate")
    if system.unit == "rad":
        return rows.time, np.cumsum(rows.q, axis=1)
    return rows.time, rows.q[:, [1, 0]]


def error(run):
    """The largest difference of the run from the reference."""
    times, values = observed(run.system, simulate(run))
    ref_times, ref = reference(run.system)
    if len(times) != len(ref_times) \
            or np.max(np.abs(times - ref_times)) > 1e-9:
        raise RuntimeError("%s: rows at other times than the reference's"
                           " (%d rows, %d expected)"
                           % (run.path, len(times), len(ref_times)))
    return float(np.max(np.abs(values - ref)))


@dataclass
class Combination:
    """An integrator, nIter and system at deltaT, /2, /4: errors, orders."""
    system: System
    solver: str
    n_iter: str
    errors: tuple = ()

    def delta_ts(self):
        return [self.system.delta_t/2**k for k in range(3)]

    def orders(self):
        e = self.errors
        return [math.log2(e[k]/e[k + 1]) if e[k + 1] > 0 else math.inf
                for k in range(len(e) - 1)]

    def failures(self):
        """What fails: empty if the combination passes."""
        why = []
        orders = self.orders()
        if self.system.order == 1:
            # the load fixed in the step: first order, no better, no worse
            if max(abs(p - 1) for p in orders) > 1 - FIRST_ORDER:
                why.append("orders %s, not within %g-%g" % (
                    " ".join("%.2f" % p for p in orders), FIRST_ORDER,
                    2 - FIRST_ORDER))
        elif max(self.errors[1:]) > ROUND_OFF and min(orders) < MIN_ORDER:
            why.append("order %.2f < %g" % (min(orders), MIN_ORDER))
        if self.system.limit and self.errors[0] > self.system.limit:
            why.append("error %.3g %s > %g at deltaT %g" % (
                self.errors[0], self.system.unit, self.system.limit,
                self.system.delta_t))
        return why

    def line(self):
        why = self.failures()
        return "%s %s %s nIter %s: errors %s %s at deltaT %s, orders %s%s" % (
            "FAIL" if why else "PASS", self.system.name, self.solver,
            self.n_iter, " ".join("%.3g" % e for e in self.errors),
            self.system.unit, " ".join("%g" % d for d in self.delta_ts()),
            " ".join("%.2f" % p for p in self.orders()),
            (": " + "; ".join(why)) if why else "")


def table(combinations):
    """Markdown: a row per combination."""
    rows = ["| system | integrator | nIter | error at dt | dt/2 | dt/4 |"
            " order | order | |",
            "|---|---|---|---:|---:|---:|---:|---:|---|"]
    for c in combinations:
        rows.append("| %s | %s | %s | %s | %s | %s |" % (
            c.system.name, c.solver, c.n_iter,
            " | ".join("%.3g %s" % (e, c.system.unit) for e in c.errors),
            " | ".join("%.2f" % p for p in c.orders()),
            "FAIL" if c.failures() else "PASS"))
    return "\n".join(rows) + "\n"


def evaluate(combinations, root, jobs):
    """Every combination's three runs, jobs at a time."""
    runs = [(c, Run(c.system, c.solver, c.n_iter, dt, root))
            for c in combinations for dt in c.delta_ts()]
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        errors = list(pool.map(lambda cr: error(cr[1]), runs))
    for i, c in enumerate(combinations):
        c.errors = tuple(errors[3*i:3*i + 3])


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-systems", nargs="+", default=list(SYSTEMS),
                        choices=list(SYSTEMS))
    parser.add_argument("-solvers", nargs="+", default=list(SOLVERS),
                        choices=SOLVERS)
    parser.add_argument("-nIter", dest="n_iter", nargs="+",
                        default=list(NITERS),
                        choices=NITERS)
    parser.add_argument("-dir", default="/tmp/flapFoam-integratorOrder")
    parser.add_argument("-jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("-out", help="the table, markdown")
    args = parser.parse_args(argv)
    combinations = [Combination(SYSTEMS[s], solver, n)
                    for s in args.systems for solver in args.solvers
                    for n in args.n_iter]
    os.makedirs(args.dir, exist_ok=True)
    evaluate(combinations, args.dir, max(1, args.jobs))
    for c in combinations:
        print(c.line())
    text = table(combinations)
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    return 1 if any(c.failures() for c in combinations) else 0


if __name__ == "__main__":
    sys.exit(run_tool(main))
