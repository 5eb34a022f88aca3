# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The paper's integrator study on the quasi-steady model: the single-wing
drone (its dictionary unchanged but for the integrator) flown from rest for
N cycles by rigidBodySimulate -bodyLoad aerodynamics with Newmark (nIter 1
and 3) and symplectic (nIter 1 and 3) at several time steps; the final
positions x, z against Newmark nIter 3 at the same step and against a
converged reference (Newmark nIter 3, the finest step / 4).

    flapfoam qs_integrators -dict FILE -cycles 20
        -steps "500 5000" -dir DIR -o TABLE.md

Writes a markdown table (differences in mm and in % of the reference's
|x|, |z|) and prints it.
"""

import argparse
import os
from dataclasses import dataclass

from flapfoam.studies.qs_sweep import Model, Sweep
from flapfoam.errors import run_tool

INTEGRATORS = (("Newmark", 1), ("Newmark", 3), ("symplectic", 1),
               ("symplectic", 3))


@dataclass
class Study:
    """The study's dictionary, working folder and cycles flown."""
    dict: str
    dir: str
    cycles: int


def flight(study, solver, n_iter, steps):
    """(xEnd, zEnd, seconds, frequency) of one run."""
    work = os.path.join(study.dir, "%s-%d-%d" % (solver, n_iter, steps))
    os.makedirs(work, exist_ok=True)
    model = Model(study.dict, work, solver, n_iter)
    row = Sweep(model, work, study.cycles, steps).run("run", {})
    return row["xEnd"], row["zEnd"], row["seconds"], \
        model.defaults["frequency"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-dict", required=True)
    parser.add_argument("-cycles", type=int, default=20)
    parser.add_argument("-steps", default="500 5000",
                        help="time steps per cycle")
    parser.add_argument("-dir", required=True)
    parser.add_argument("-o", required=True)
    args = parser.parse_args()
    steps = [int(s) for s in args.steps.split()]
    study = Study(args.dict, args.dir, args.cycles)
    x_ref, z_ref, _, _ = flight(study, "Newmark", 3, 4*max(steps))
    lines = [
        "| integrator | nIter | steps/cycle | x(T) [mm] | z(T) [mm] |"
        " x - Newmark 3 [mm] (%) | z - Newmark 3 [mm] (%) |"
        " x - converged (%) | z - converged (%) | run [s] |",
        "|---|---|---|---|---|---|---|---|---|---|"]
    summary = []
    for n in steps:
        runs = {(s, i): flight(study, s, i, n) for s, i in INTEGRATORS}
        x_n, z_n, _, _ = runs[("Newmark", 3)]
        summary.append(
            "%d steps per cycle (deltaT %.3g s): the largest difference from"
            " Newmark nIter 3 is %.2g %% in x and %.2g %% in z (paper:"
            " within 1 %%)." % (n, 1/(n*runs[("Newmark", 3)][3]),
                               max(100*abs(x - x_n)/abs(x_n)
                                   for x, _, _, _ in runs.values()),
                               max(100*abs(z - z_n)/abs(z_n)
                                   for _, z, _, _ in runs.values())))
        for (s, i), (x, z, sec, _) in runs.items():
            lines.append(
                "| %s | %d | %d | %.4f | %.4f | %+.2e (%.2g) | %+.2e (%.2g)"
                " | %.2g | %.2g | %.2f |"
                % (s, i, n, 1e3*x, 1e3*z, 1e3*(x - x_n),
                   100*abs(x - x_n)/abs(x_n), 1e3*(z - z_n),
                   100*abs(z - z_n)/abs(z_n), 100*abs(x - x_ref)/abs(x_ref),
                   100*abs(z - z_ref)/abs(z_ref), sec))
    lines += [""] + summary + [""]
    lines.append("Converged reference (Newmark nIter 3, %d steps per cycle):"
                 " x(T) = %.4f mm, z(T) = %.4f mm."
                 % (4*max(steps), 1e3*x_ref, 1e3*z_ref))
    with open(args.o, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    run_tool(main)
