# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Compare the multibody motion of two drone runs (eABAMeshMotion) that
differ only in the overset stencil: each body's force of bodies.dat and
the trajectory of joints.dat, rows matched by time (read by
flapfoam.io.run_series, joined over the restarts).

    flapfoam overset_motion REF CASE [-forceTol 0] [-qTol 0]
        [-columns q_0,qDot_0,q_1,qDot_1] [-bodies wing]

(applications/test/overset/compareMotion runs the cases.)

  force (each body of the comma-separated -bodies): max over the rows and
         components of |F_CASE - F_REF| / max|F_REF|
         (max of |F| over the rows of the reference run); PASS if <= forceTol,
         each component reported.
  trajectory: check_run's relative difference |a - b| / max(|a|, |b|,
         floor), floor = 1e-3 x max |value| of that column over REF's rows;
         PASS if <= qTol for each of the columns.
One PASS/FAIL line per check; exit status 1 on a failure.
"""

import argparse
import os
import sys

import numpy as np

from flapfoam.checks import check_run
from flapfoam.errors import run_tool
from flapfoam.io import run_series


def tables(case):
    """The run's eABAMeshMotion tables (a run_series.RunSeries)."""
    return run_series.read(case, tables="eABAMeshMotion")


def arguments(argv):
    ap = argparse.ArgumentParser(prog="flapfoam overset_motion",
                                 description=__doc__.split("\n\n")[0])
    ap.add_argument("ref")
    ap.add_argument("case")
    ap.add_argument("-forceTol", dest="force_tol", type=float, default=0.0)
    ap.add_argument("-qTol", dest="q_tol", type=float, default=0.0)
    ap.add_argument("-columns", default="q_0,qDot_0,q_1,qDot_1")
    ap.add_argument("-bodies", default="wing")
    return ap.parse_args(argv)


def forces(a, runs, name, ref_name):
    """Each body's force against the reference's (runs: their tables,
    the reference's first); 0 if all pass, else 1."""
    status = 0
    A, B = runs
    ia, ib = check_run.match_rows(A.time[:, None], B.time[:, None])
    for body in a.bodies.split(","):
        check = "%s %s force" % (name, body)
        if len(ia) == 0 or len(ia) != len(A.time) or \
                len(ib) != len(B.time):
            status |= check_run.report(
                False, check,
                "rows at different times (%d common, %d and %d rows)"
                % (len(ia), len(A.time), len(B.time)))
            continue
        FA, FB = A.bodies[body].force, B.bodies[body].force
        scale = float(np.linalg.norm(FA, axis=1).max()) + 1e-300
        rel = np.abs(FA[ia] - FB[ib]).max(axis=0)/scale
        status |= check_run.report(
            float(rel.max()) <= a.force_tol, check,
            "vs %s, %d rows: max |dF|/max|F| %.2e (tol %g): %s "
            "(max|F| %.4g N)"
            % (ref_name, len(ia), rel.max(), a.force_tol,
               ", ".join("F%s %.1e" % (c, r) for c, r in zip("xyz", rel)),
               scale))

    return status


def trajectory(a, runs, name, ref_name):
    """The joints' columns against the reference's (check_run's relative
    difference with a floor; runs as forces'); 0 if they pass, else 1."""
    status = 0
    ca, A = runs[0].joints_table()
    cb, B = runs[1].joints_table()
    ia, ib = check_run.match_rows(A, B)
    if len(ia) == 0 or len(ia) != len(A) or len(ib) != len(B):
        status |= check_run.report(
            False, "%s trajectory" % name,
            "rows at different times (%d common, %d and %d rows)"
            % (len(ia), len(A), len(B)))
    else:
        worst = {}
        for col in a.columns.split(","):
            i, k = ca.index(col), cb.index(col)
            floor = 1e-3*np.abs(A[:, i]).max() + 1e-300
            worst[col] = float(
                check_run.rel_diff(A[ia, i], B[ib, k], floor).max())
        max_rel = max(worst.values())
        status |= check_run.report(
            max_rel <= a.q_tol, "%s trajectory" % name,
            "vs %s, %d rows: max relative difference %.2e (tol %g): %s"
            % (ref_name, len(ia), max_rel, a.q_tol,
               ", ".join("%s %.1e" % kv for kv in worst.items())))
    return status


def main(argv=None):
    a = arguments(argv)
    name = os.path.basename(os.path.normpath(a.case))
    ref_name = os.path.basename(os.path.normpath(a.ref))
    runs = tables(a.ref), tables(a.case)
    return forces(a, runs, name, ref_name) | \
        trajectory(a, runs, name, ref_name)


if __name__ == "__main__":
    sys.exit(run_tool(main))
