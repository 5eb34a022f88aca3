#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The scaling model against measured runs (flapfoam.scalingValidate).

    bench/scaling/validate.py [ARCHIVE ...] [-calibrate PATTERN ...]
        [-measuredIterations] [-o FILE] [-causes FILE]

ARCHIVE: a .tar.gz in the format of bench/scaling/measured/
scaling-16core-*.tar.gz or a folder with its runs.tsv and runs/ (default:
both committed archives).  Prints per run (np >= 2) level, stencil, method,
np, measured and model step, their ratio; the largest errors, the ranking
of the methods, and last "model within X % of N measured runs".
-calibrate: fit the model's constants on the runs matching the patterns
(level/stencil-method-npN, fnmatch; "default": the committed set) instead
of using the committed ones.  -o: also a markdown table; -causes: the
PIMPLE gap of each method against the fastest one, cause by cause
(markdown).  Needs PYTHONPATH with the project's scripts/ (etc/bashrc).
"""

import argparse
import glob
import os
import sys

try:
    from flapfoam import scalingCauses, scalingModel, scalingValidate as sv
except ImportError:
    sys.exit("validate.py: no flapfoam package: source etc/bashrc or set "
             "PYTHONPATH=<flapFoam>/scripts")

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("archives", nargs="*", default=sorted(glob.glob(
        os.path.join(HERE, "measured", "scaling-16core-*.tar.gz"))))
    parser.add_argument("-calibrate", nargs="+", metavar="PATTERN")
    parser.add_argument("-measuredIterations", action="store_true")
    parser.add_argument("-o", metavar="FILE")
    parser.add_argument("-causes", metavar="FILE")
    args = parser.parse_args()
    runs = sv.read_archives(args.archives)
    patterns = scalingModel.CALIBRATION_RUNS
    cal = scalingModel.CALIBRATION
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
            f.write("\n".join(scalingCauses.report(runs, cal)) + "\n")


if __name__ == "__main__":
    main()
