# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The bound stage's table (bench/scaling/run -stages bound).

    flapfoam scaling_bound -dir DIR -levels "fine ..." -np "16 32 48"
        -poses "0 5 10 15" -o FILE.md

At kept poses K of the couplings, two decompositions counted at that pose
(oversetCouplingsReport -pose K): "cycle", oversetGraph of the cycle's
couplings (the structure stage's, the one a run uses), and "pose K",
oversetGraph made for pose K alone (what a decomposition moved with the
wing at every step would give, as far as METIS finds it).  Per level and
number of ranks, means over the poses: acceptors with a donor on another
rank, with every donor on another rank (the stock log's "remote"),
donor-acceptor pairs with the donor remote, processor faces and the
values the busiest rank receives per linear-solver sweep (processor faces
plus remote donor cells) against scotch's (the structure stage's), cells
and overset work max/mean.  Reads
DIR/<level>/bound/{cycle,pose}<K>-np<N>.report and
DIR/<level>/structure/scotch-np<N>.report.
"""

import argparse
import os
import sys

import numpy as np

from flapfoam.bench import rank_tables
from flapfoam.errors import run_tool

REPORT = "oversetCouplingsReport"


def counts(fname):
    """What one report gives: the shares and imbalances, processor faces
    (each counted once)."""
    t = rank_tables.read_table(fname, REPORT)
    total = t.total
    sampled = max(total["sampledAcceptors"], 1.0)
    work = rank_tables.column(t, "oversetWork")
    cells = rank_tables.column(t, "cells")
    sweep = rank_tables.column(t, "processorFaces") \
        + rank_tables.column(t, "remoteDonors")
    return {"remote": total["remoteAcceptors"]/sampled,
            "allRemote": total["allRemoteAcceptors"]/sampled,
            "pairs": total["remotePairs"]/max(total["pairs"], 1.0),
            "faces": total["processorFaces"]/2,
            "cells": cells.max()/cells.mean(),
            "work": work.max()/max(work.mean(), 1e-300),
            "sweep": sweep.max()}


def mean_counts(files):
    """The mean of counts() over files."""
    each = [counts(f) for f in files]
    return {k: float(np.mean([c[k] for c in each])) for k in each[0]}


def level_rows(dir_, level, nps, poses):
    """Table rows of one level: per number of ranks, cycle then pose."""
    rows = []
    for n in nps:
        scotch = os.path.join(dir_, level, "structure",
                              "scotch-np%d.report" % n)
        ref = counts(scotch) if os.path.exists(scotch) else None
        for kind in ("cycle", "pose"):
            c = mean_counts([os.path.join(dir_, level, "bound",
                                          "%s%d-np%d.report" % (kind, k, n))
                             for k in poses])
            ratio = ["%.2f" % (c[k]/ref[k]) if ref else "-"
                     for k in ("faces", "sweep")]
            name = "cycle (a run's)" if kind == "cycle" \
                else "each pose its own"
            rows.append("| %d | %s | %.1f %% | %.1f %% | %.1f %% | %d | %s "
                        "| %.0f | %s | %.3f | %.2f |"
                        % (n, name, 100*c["remote"], 100*c["allRemote"],
                           100*c["pairs"], c["faces"], ratio[0], c["sweep"],
                           ratio[1], c["cells"], c["work"]))
    return rows


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-dir", required=True)
    ap.add_argument("-levels", required=True)
    ap.add_argument("-np", required=True)
    ap.add_argument("-poses", required=True)
    ap.add_argument("-o", required=True)
    args = ap.parse_args(argv)
    nps = [int(n) for n in args.np.split()]
    poses = [int(k) for k in args.poses.split()]
    lines = [
        "# What a decomposition moved with the wing could give (counted)", "",
        "oversetGraph at kept poses %s of the cycle: the cycle's "
        "decomposition (what a run uses) against one made for that pose "
        "alone (`oversetGraphCoeffs { pose K; }`: what re-decomposing at "
        "every step would give, as far as METIS finds it), both counted at "
        "the pose (`oversetCouplingsReport -pose K`); means over the poses. "
        "Remote acceptors: with a donor on another rank; all remote: every "
        "donor on another rank (the stock log's `remote`). Sweep values "
        "max: what the busiest rank receives per linear-solver sweep, "
        "processor faces plus the donor cells on other ranks (each once; "
        "v1912 puts them in the matrix as remote-stencil interfaces). "
        "Processor faces and sweep values against the structure stage's "
        "scotch (over the cycle). Overset work at one pose: acceptors and "
        "donors (no holes)." % ", ".join(map(str, poses)), ""]
    for level in args.levels.split():
        lines += ["## SW %s" % level, "",
                  "| ranks | decomposition | remote acceptors | all remote "
                  "| remote pairs | processor faces | vs scotch | sweep values "
                  "max | vs scotch | cells max/mean | overset work max/mean |",
                  "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        lines += level_rows(args.dir, level, nps, poses) + [""]
    with open(args.o, "w") as f:
        f.write("\n".join(lines))
    print("bound: wrote %s" % args.o)


if __name__ == "__main__":
    run_tool(main, sys.argv[1:])
