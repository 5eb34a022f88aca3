# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Compare overset runs of the same case: cellTypes per written time against a
reference run (match fraction, cells differing per type pair) and the
stepTimers medians of the overset parts.

    flapfoam overset_cell_types -dir DIR -reference NAME [-minMatch F]
        [-skip N] NAME...

DIR/NAME is a case with time folders holding cellTypes and
postProcessing/stepTimers/0/stepTimers.dat (applications/test/overset:
compareMotion, compareStencils).  Exit status 1 if a match fraction is
below -minMatch (default 1: every cell) or a run has no cellTypes.
"""

import argparse
import glob
import os
import sys

import numpy as np

from flapfoam.errors import run_tool
from flapfoam.io import foam_mesh
from flapfoam.io.step_timers import read_file
from flapfoam.io.tables import time_value


def times(case):
    out = []
    for d in glob.glob(os.path.join(case, "*")):
        b = os.path.basename(d)
        t = time_value(b, 0.0)
        if t > 0 and os.path.isfile(os.path.join(d, "cellTypes")):
            out.append((t, b))
    return sorted(out)


def timers(case, skip):
    """{column: (median, steps)} of the stencil (oversetStencil and its
    laps), the overset parts and the step, the first skip steps left out;
    {} without stepTimers.dat."""
    path = os.path.join(case, "postProcessing", "stepTimers", "0",
                        "stepTimers.dat")
    if not os.path.isfile(path):
        return {}
    rows = read_file(path)[skip:]
    # The stencil: oversetStencil plus its nested laps oversetStencil<Lap>
    for r in rows:
        r["stencil"] = sum(v for k, v in r.items()
                           if k.startswith("oversetStencil"))
    cols = ["stencil", "oversetMovePoints", "overset", "total"] + LAPS
    return {c: (float(np.median([r.get(c, 0.0) for r in rows])), len(rows))
            for c in cols}


LAPS = ["oversetStencil" + p for p in
        ("Transform", "Voxels", "Holes", "Donors", "Flood", "Weights")]


def compare(ref, ref_times, case, name):
    """The worst match fraction of case's cellTypes against ref's over
    ref_times, a line per time (cells differing per type pair); None if a
    time has no cellTypes in case."""
    worst = 1.0
    for _, tn in ref_times:
        f = os.path.join(case, tn, "cellTypes")
        if not os.path.isfile(f):
            print("FAIL %s: no cellTypes at %s" % (name, tn))
            return None
        r = foam_mesh.read_scalar_field(os.path.join(ref, tn, "cellTypes"))
        c = foam_mesh.read_scalar_field(f)
        match = float(np.mean(r == c))
        worst = min(worst, match)
        diff = r != c
        pairs = {}
        for x, y in zip(r[diff].astype(int), c[diff].astype(int)):
            pairs[(x, y)] = pairs.get((x, y), 0) + 1
        print("  %-26s t=%-8s match %.6f  differing %d %s"
              % (name, tn, match, int(diff.sum()),
                 " ".join("%d->%d:%d" % (k[0], k[1], v)
                          for k, v in sorted(pairs.items()))))
    return worst


def print_timers(folder, names, skip):
    """The stepTimers medians of the runs folder/NAME, and the speed-up of
    the cached stencil update against the stock one timed alike."""
    print("\nstepTimers medians [s] (first %d steps skipped):" % skip)
    print("  (stencil = oversetStencil + its laps, inside the stencil's update;"
          " the stock\n   inverseDistance run has no stencil timer: its"
          " stencil is inside oversetMovePoints)")
    print("  %-26s %10s %17s %10s %10s %6s   laps: %s"
          % ("run", "stencil", "oversetMovePoints", "overset",
             "total", "steps", " ".join(p[14:] for p in LAPS)))
    stencil = {}
    for name in names:
        tm = timers(os.path.join(folder, name), skip)
        if not tm:
            print("  %-26s (no stepTimers.dat)" % name)
            continue
        stencil[name] = tm["stencil"][0]
        print("  %-26s %10.5f %17.5f %10.5f %10.5f %6d   %s"
              % (name, tm["stencil"][0], tm["oversetMovePoints"][0],
                 tm["overset"][0], tm["total"][0], tm["total"][1],
                 " ".join("%.5f" % tm[p][0] for p in LAPS)))
    # The stock update timed by the same timer (octreeStock) against the
    # cached update
    if stencil.get("octreeStock") and stencil.get("octreeInverseDistance"):
        print("\nstencil update speed-up octreeInverseDistance vs stock"
              " (octreeStock), ratio of medians: %.1f"
              % (stencil["octreeStock"] / stencil["octreeInverseDistance"]))


def main(argv=None):
    ap = argparse.ArgumentParser(prog="flapfoam overset_cell_types",
                                 description=__doc__.split("\n\n")[0])
    ap.add_argument("-dir", required=True)
    ap.add_argument("-reference", required=True)
    ap.add_argument("-minMatch", dest="min_match", type=float, default=1.0)
    ap.add_argument("-skip", type=int, default=2,
                    help="first steps left out of the timer medians")
    ap.add_argument("names", nargs="+")
    a = ap.parse_args(argv)

    ok = True
    ref = os.path.join(a.dir, a.reference)
    ref_times = times(ref)
    if not ref_times:
        print("FAIL no cellTypes in %s" % ref)
        return 1

    for name in a.names:
        if name == a.reference:
            continue
        worst = compare(ref, ref_times, os.path.join(a.dir, name), name)
        if worst is None:
            ok = False
            continue
        status = "PASS" if worst >= a.min_match else "FAIL"
        ok = ok and worst >= a.min_match
        print("%s %s: cellTypes match vs %s >= %.6f over %d times "
              "(required %.4f)"
              % (status, name, a.reference, worst, len(ref_times),
                 a.min_match))

    print_timers(a.dir, a.names, a.skip)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(run_tool(main))
