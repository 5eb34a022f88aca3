#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The scaling model against measured runs (flapfoam.scaling_validate).

    bench/scaling/validate.py [ARCHIVE ...] [-rounds FILE ...]
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
each method against the fastest one, cause by cause (markdown).  Needs
PYTHONPATH with the project's scripts/ (etc/bashrc).
"""

import argparse
import os
import sys

try:
    from flapfoam import scaling_causes, scaling_model, scaling_validate as sv
except ImportError:
    sys.exit("validate.py: no flapfoam package: source etc/bashrc or set "
             "PYTHONPATH=<flapFoam>/scripts")

HERE = os.path.dirname(os.path.abspath(__file__))
MEASURED = os.path.join(HERE, "measured")
SESSIONS = [os.path.join(MEASURED, f) for f in (
    "scaling-16core-coarse.tar.gz", "scaling-16core-medium.tar.gz",
    "device-2026-11-26/session2-round3.tar.gz")]
ROUNDS = [os.path.join(MEASURED, "device-2026-11-26/session1/runTimed.log")]


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("archives", nargs="*")
    parser.add_argument("-rounds", nargs="+", metavar="FILE", default=[])
    parser.add_argument("-levels", default="coarse medium")
    parser.add_argument("-calibrate", nargs="+", metavar="PATTERN")
    parser.add_argument("-measuredIterations", action="store_true")
    parser.add_argument("-o", metavar="FILE")
    parser.add_argument("-causes", metavar="FILE")
    args = parser.parse_args()
    if not args.archives:
        args.archives, args.rounds = SESSIONS, args.rounds or ROUNDS
    return args


def main():
    args = arguments()
    runs = sv.read_archives(args.archives, rounds=args.rounds,
                            level_names=args.levels.split())
    patterns = scaling_model.CALIBRATION_RUNS
    cal = scaling_model.CALIBRATION
    if args.calibrate:
        if args.calibrate != ["default"]:
            patterns = tuple(args.calibrate)
        cal = sv.rounded(sv.calibrate(runs, patterns))
    print("calibration: %s\ncalibrated on: %s" % (cal, " ".join(patterns)))
    rows = sv.compare(runs, cal, patterns, args.measuredIterations)
    print("\n".join(sv.table(rows)))
    if args.o:
        with open(args.o, "w") as f:
            f.write("\n".join(sv.table(rows, markdown=True)) + "\n")
    if args.causes:
        with open(args.causes, "w") as f:
            f.write("\n".join(scaling_causes.report(runs, cal)) + "\n")


if __name__ == "__main__":
    main()
