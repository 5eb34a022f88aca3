#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Two-wing drone: the residual asymmetry of the overset mesh about the plane
y = 0, from constant/polyMesh and 0/zoneID of a run or mesh folder.

    mirrorCheck.py [-case DIR] [-tol T]

Each cell's centre (the mean of its face centres) mirrored (y -> -y) is
matched to the nearest cell centre of the mirror zone (background and body:
themselves; left and right wing: each other, zoneID 1 <-> 3), and the
largest distance is printed per zone, in metres: "PASS mirror ..." if every
one is at most T (default 1e-9 m), else "FAIL".  The wings' cells are also
compared by label (cell i of the right wing is the mirror image of cell i
of the left one, placeMesh.py): the largest |x_i - x'_i|, |y_i + y'_i|,
|z_i - z'_i|, at most T.  (Measured on tiny: 4.6e-17 m at most, the
round-off of the centres: the points are mirrored exactly.)  numpy only; exit status 1 if a check fails.
"""

import argparse
import os
import sys
from types import SimpleNamespace

import numpy as np

from flapfoam.checks.mesh_checks import cell_centres_approx
from flapfoam.io import foam_mesh

ZONES = {0: "body", 1: "leftWing", 2: "background", 3: "rightWing"}
PARTNER = {0: 0, 1: 3, 2: 2, 3: 1}


def centres(case):
    """(cell centres, zoneID) of the case's mesh."""
    pm = os.path.join(case, "constant", "polyMesh")
    offs, verts = foam_mesh.read_faces(os.path.join(pm, "faces"))
    owner = foam_mesh.read_labels(os.path.join(pm, "owner"))
    mesh = SimpleNamespace(offs=offs, verts=verts, owner=owner,
                           neighbour=foam_mesh.read_labels(
                               os.path.join(pm, "neighbour")))
    n = foam_mesh.read_n_cells(os.path.join(pm, "owner"))
    c, _ = cell_centres_approx(
        foam_mesh.read_points(os.path.join(pm, "points")), mesh, n)
    zone = np.rint(foam_mesh.read_scalar_field(
        os.path.join(case, "0", "zoneID"))).astype(int)
    return c, zone


def nearest_distance(a, b, h=5e-4):
    """For each point of a, the distance to the nearest point of b (a
    bucket grid of size h, the 27 buckets around; a point with none there
    gets inf)."""
    keys = np.floor(b/h).astype(np.int64)
    buckets = {}
    for i, k in enumerate(map(tuple, keys)):
        buckets.setdefault(k, []).append(i)
    out = np.full(len(a), np.inf)
    offsets = [(i, j, k) for i in (-1, 0, 1) for j in (-1, 0, 1)
               for k in (-1, 0, 1)]
    for n, k in enumerate(map(tuple, np.floor(a/h).astype(np.int64))):
        cand = [i for o in offsets
                for i in buckets.get((k[0] + o[0], k[1] + o[1],
                                      k[2] + o[2]), ())]
        if cand:
            out[n] = np.min(np.linalg.norm(b[cand] - a[n], axis=1))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[1])
    ap.add_argument("-case", default=".")
    ap.add_argument("-tol", type=float, default=1e-9)
    a = ap.parse_args(argv)
    c, zone = centres(a.case)
    m = c*np.array([1.0, -1.0, 1.0])
    ok = True
    for z, name in ZONES.items():
        d = nearest_distance(m[zone == z], c[zone == PARTNER[z]])
        worst = float(d.max()) if len(d) else np.inf
        ok &= worst <= a.tol
        print("%s mirror %s: %d cells, largest distance of a mirrored "
              "centre to the nearest %s centre %.3g m (tolerance %g)"
              % ("PASS" if worst <= a.tol else "FAIL", name, len(d),
                 ZONES[PARTNER[z]], worst, a.tol))
    left, right = c[zone == 1], c[zone == 3]
    if left.shape == right.shape:
        e = np.abs(np.column_stack([left[:, 0] - right[:, 0],
                                    left[:, 1] + right[:, 1],
                                    left[:, 2] - right[:, 2]])).max(axis=0)
        same = bool(np.all(e <= a.tol))
        print("%s mirror wings by label: max |x - x'| %.3g, |y + y'| %.3g, "
              "|z - z'| %.3g m" % ("PASS" if same else "FAIL", *e))
        ok &= same
    else:
        print("FAIL mirror wings: %d and %d cells" % (len(left), len(right)))
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
