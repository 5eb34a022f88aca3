#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Checks of the single-wing drone overset mesh (constant/polyMesh):

  - cells per cellZone ("background", "wing") and in total, against the
    target of the level (tiny: <= 30k; coarse/medium/fine/finePlus: within
    15 % of 71k/214k/501k/808k, paper Fig. "grid study");
  - area of the "wing" patch against the analytic wetted area of the plate
    (2 S + t (P/2 + c_r), scripts/wingGeometry.py): within 2 %;
  - patches present with the expected types (wing: wall, oversetPatch:
    overset, farField: patch).

Usage: meshCheck.py [-case DIR] [-level LEVEL] [-json FILE]
Prints one "PASS ..." or "FAIL ..." line per check; exit status 1 if any
check fails.
"""

import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foamMesh as fm      # noqa: E402
import wingGeometry as geo  # noqa: E402

TARGETS = {"coarse": 71e3, "medium": 214e3, "fine": 501e3, "finePlus": 808e3}
TINY_MAX = 30000
COUNT_TOL = 0.15
AREA_TOL = 0.02


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("-case", default=".")
    ap.add_argument("-level", default=None,
                    help="level (default: from mesh/meshGen.json)")
    ap.add_argument("-json", default=None, help="write the results here")
    args = ap.parse_args(argv)

    pm = os.path.join(args.case, "constant", "polyMesh")
    level = args.level
    gen = os.path.join(args.case, "mesh", "meshGen.json")
    if level is None and os.path.exists(gen):
        with open(gen) as fh:
            level = json.load(fh)["level"]

    ok = True
    res = {"level": level}

    def report(passed, msg):
        nonlocal ok
        ok = ok and passed
        print(("PASS " if passed else "FAIL ") + msg)

    nCells = fm.readNCells(os.path.join(pm, "owner"))
    zones = fm.readZoneSizes(os.path.join(pm, "cellZones"))
    res.update(nCells=nCells, zones=zones)
    print("cells: total %d" % nCells + "".join(
        ", %s %d (%.1f %%)" % (z, n, 100.0*n/nCells)
        for z, n in zones.items()))
    report(set(zones) == {"background", "wing"}
           and sum(zones.values()) == nCells,
           "cellZones background + wing cover the mesh (%s)"
           % ", ".join(zones))
    if level == "tiny":
        report(nCells <= TINY_MAX, "tiny: %d cells <= %d" % (nCells, TINY_MAX))
    elif level in TARGETS:
        tgt = TARGETS[level]
        err = nCells/tgt - 1
        res["countError"] = err
        report(abs(err) <= COUNT_TOL, "%s: %d cells, target %d (%+.1f %%, "
               "tolerance %.0f %%)" % (level, nCells, tgt, 100*err,
                                       100*COUNT_TOL))

    bnd = fm.readBoundary(os.path.join(pm, "boundary"))
    expect = {"wing": "wall", "oversetPatch": "overset", "farField": "patch"}
    report(all(bnd.get(p, {}).get("type") == t for p, t in expect.items())
           and set(bnd) == set(expect),
           "patches %s" % ", ".join("%s(%s)" % (p, d["type"])
                                     for p, d in bnd.items()))

    pts = fm.readPoints(os.path.join(pm, "points"))
    offs, verts = fm.readFaces(os.path.join(pm, "faces"))
    w = bnd["wing"]
    faces = np.arange(w["startFace"], w["startFace"] + w["nFaces"])
    Sf = fm.faceAreasVec(pts, offs, verts, faces)
    magSf = np.linalg.norm(Sf, axis=1)
    area = float(magSf.sum())
    exact = geo.wingArea()
    err = area/exact - 1
    res.update(wingArea=area, wingAreaAnalytic=exact, wingAreaError=err,
               wingFaces=int(w["nFaces"]))
    report(abs(err) <= AREA_TOL,
           "wing patch area %.6e m^2, analytic %.6e m^2 (%+.3f %%, "
           "tolerance %.0f %%; %d faces)"
           % (area, exact, 100*err, 100*AREA_TOL, w["nFaces"]))

    # breakdown in the wing frame: top + bottom (2 S) and the edge band
    phi = alpha = 0.0
    if os.path.exists(gen):
        with open(gen) as fh:
            pose = json.load(fh).get("pose", {})
        phi = np.radians(pose.get("phiDeg", 0.0))
        alpha = np.radians(pose.get("alphaDeg", 0.0))
    Rz = np.array([[np.cos(phi), -np.sin(phi), 0],
                   [np.sin(phi), np.cos(phi), 0], [0, 0, 1]])
    Ry = np.array([[np.cos(alpha), 0, np.sin(alpha)], [0, 1, 0],
                   [-np.sin(alpha), 0, np.cos(alpha)]])
    nz = np.abs((Sf @ (Rz @ Ry))[:, 2])/magSf      # |n . z_wing|
    flat = float(magSf[nz > 0.5].sum())
    band = area - flat
    flatExact = 2*geo.planformArea()
    bandExact = exact - flatExact
    res.update(topBottomArea=flat, topBottomAnalytic=flatExact,
               edgeArea=band, edgeAnalytic=bandExact)
    print("     top + bottom %.6e m^2 (2 S = %.6e, %+.3f %%), edge band "
          "%.6e m^2 (t (P/2 + c_r) = %.6e, %+.3f %%)" % (
              flat, flatExact, 100*(flat/flatExact - 1), band, bandExact,
              100*(band/bandExact - 1)))

    if args.json:
        with open(args.json, "w") as fh:
            json.dump(res, fh, indent=2)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
