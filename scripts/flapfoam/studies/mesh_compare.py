# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
How much a mesh moves a drone run's answer: two runs of the same flight
(e.g. BW coarse against tiny), cycle by cycle.

    flapfoam mesh_compare REF RUN [-cycles N] [-pitchJoint 2] [-period T]
        [-md FILE] [-summary FILE -key NAME]

Per whole cycle k = 1..N (default: every cycle both runs hold) of REF (the
reference, e.g. tiny) and RUN (e.g. coarse), from their flight data (a run
folder or a flightData.h5):

    pitch       the pitch joint's angle at the cycle's end [deg]
    F_z, F_x    the cycle-mean fluid force on all bodies, global frame [N]
    M_y         the cycle-mean fluid moment on all bodies about y [N m]
                (each body's as its flight data holds it: the BW wing's
                about the body's centre of mass, the body's about its own)

and each one's difference, RUN - REF, in % of |REF|'s value (a value near
0 makes that % large: the absolute difference is beside it).  The cycle
means weigh each row by its time step (the first row, the initial state
without loads, left out).  -md FILE: the table; -summary FILE -key NAME:
{NAME: {quantity: [% per cycle]}, NAME_max: {quantity: the largest |%|}}
merged into a results folder's summary.json.  numpy, h5py.
"""

import argparse
import math
import sys

import numpy as np

from flapfoam.errors import FlapFoamError, run_tool
from flapfoam.studies.compare_models import cycle_end_angles, cycle_means
from flapfoam.studies.flight_modes import read_series
from flapfoam.studies.qs_case import write_summary

QUANTITIES = ("pitch_deg", "Fz_N", "Fx_N", "My_Nm")


def per_cycle(case, period, pitch_joint):
    """{quantity: [value per whole cycle]} of a run."""
    s = read_series(case)
    loaded = [b for b in s.bodies.values() if b.force is not None]
    if not loaded:
        raise FlapFoamError("%s: no body with a fluid force in its flight"
                            " data" % case)
    force = sum(b.force for b in loaded)
    moment = sum(b.moment for b in loaded if b.moment is not None)
    forces = cycle_means(s.time, force[:, [2, 0]], period)
    moments = cycle_means(s.time, np.column_stack([moment[:, 1]]*2), period)
    n = len(forces)
    return {"pitch_deg": cycle_end_angles(s.time, s.q[:, pitch_joint],
                                          period, n),
            "Fz_N": [f[1] for f in forces], "Fx_N": [f[2] for f in forces],
            "My_Nm": [m[1] for m in moments]}


def percent(a, b):
    return 100*(b - a)/abs(a) if a != 0 else math.inf


def compare(ref, run, cycles=None):
    """{quantity: [(REF, RUN, %)] per cycle} over the cycles both hold."""
    n = min(len(ref["Fz_N"]), len(run["Fz_N"]))
    if cycles is not None:
        if cycles > n:
            raise FlapFoamError("-cycles %d: the runs hold %d whole cycles"
                                " in common" % (cycles, n))
        n = cycles
    return {q: [(ref[q][k], run[q][k], percent(ref[q][k], run[q][k]))
                for k in range(n)] for q in QUANTITIES}


def table(rows):
    lines = ["| cycle | quantity | REF | RUN | RUN - REF | % of REF |",
             "|---:|---|---:|---:|---:|---:|"]
    for q in QUANTITIES:
        for k, (a, b, p) in enumerate(rows[q]):
            lines.append("| %d | %s | %.5g | %.5g | %+.3g | %+.2f |"
                         % (k + 1, q, a, b, b - a, p))
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="flapfoam mesh_compare",
        description=__doc__.split("\n\n")[1].strip())
    parser.add_argument("ref", metavar="REF")
    parser.add_argument("run", metavar="RUN")
    parser.add_argument("-cycles", type=int)
    parser.add_argument("-pitchJoint", dest="pitch_joint", type=int,
                        default=2)
    parser.add_argument("-period", type=float, default=0.05)
    parser.add_argument("-md", metavar="FILE")
    parser.add_argument("-summary", metavar="FILE")
    parser.add_argument("-key", default="coarse_vs_tiny_percent")
    args = parser.parse_args(argv)
    if not args.period > 0:
        parser.error("-period %g: not allowed (> 0)" % args.period)
    if args.cycles is not None and args.cycles < 1:
        parser.error("-cycles %d: not allowed (>= 1)" % args.cycles)
    try:
        rows = compare(per_cycle(args.ref, args.period, args.pitch_joint),
                       per_cycle(args.run, args.period, args.pitch_joint),
                       args.cycles)
    except (FlapFoamError, OSError, IndexError) as e:
        sys.exit("mesh_compare: %s" % e)
    text = table(rows)
    print(text)
    if args.md:
        with open(args.md, "w") as f:
            f.write("REF %s, RUN %s\n\n%s\n" % (args.ref, args.run, text))
    if args.summary:
        write_summary(args.summary, {
            args.key: {q: [r[2] for r in rows[q]] for q in QUANTITIES},
            args.key + "_max": {q: max(abs(r[2]) for r in rows[q])
                                for q in QUANTITIES}})


if __name__ == "__main__":
    run_tool(main)
