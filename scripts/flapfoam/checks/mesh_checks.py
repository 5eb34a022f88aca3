# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Checks of the overset mesh of a drone wing (scripts/meshCheck.py after
makeMesh, scripts/oversetCheck.py after a run written every step).

meshCheck:
Checks of the single-wing drone overset mesh (constant/polyMesh):

  - cells per cellZone ("background", "wing") and in total, against the
    target of the level (tiny: <= 30k; coarse/medium/fine/finePlus: within
    15 % of 71k/214k/501k/808k, paper Fig. "grid study");
  - area of the "wing" patch against the analytic wetted area of the plate
    (2 S + t (P/2 + c_r), flapfoam/models/wing_geometry.py): within 2 %;
  - patches present with the expected types (wing: wall, oversetPatch:
    overset, farField: patch).

Usage: meshCheck.py [-case DIR] [-level LEVEL] [-json FILE]
Prints one "PASS ..." or "FAIL ..." line per check; exit status 1 if any
check fails.

oversetCheck:
Orphan check of the overset stencil (stock inverseDistance, OpenFOAM v1912)
from the cellTypes and zoneID fields that dynamicOversetFvMesh writes at
every write time (0 calculated, 1 interpolated, 2 hole).

v1912's inverseDistance has no "orphan" cell type: an acceptor that finds
no donor (a cell next to the overset patch, or a fringe cell next to a
hole) is turned into a HOLE, and the fringe walk then goes on from it.
So, with one component and no walls in the background:

  orphans in the wing zone  = wing cells that are holes (a wing cell can only
                              become a hole by lacking donors);
  orphans in the background = background holes whose centre lies outside
                              the wing component: the legitimate holes
                              overlap the voxels of the wing patch, deep
                              inside the component, and a background cell
                              inside the component always finds a donor, so
                              a hole outside grew from an acceptor without
                              donors.  The component's pose is recovered by
                              a rigid fit of the wing patch points (time vs
                              constant/polyMesh/points0 if present, i.e.
                              the mesh as generated, else points), then
                              the hole centres are tested against the
                              component's analytic shape (offset of the
                              plate by `margin`,
                              mesh/meshGen.json).

Also reported: calculated / interpolated / hole cells per zone, the wing
cells at the overset patch that are not interpolated (must be 0), and the
smallest clearance of a background hole to the component's boundary and the
farthest hole from the wing patch, in background cell sizes h.

Usage: oversetCheck.py [-case DIR] [-time T ...] [-json FILE]
       (default: every time directory > 0 with cellTypes)
Exit status 1 if any orphan is found (or no time with cellTypes exists).
"""

import argparse
import glob
import json
import os
from dataclasses import dataclass

import numpy as np

from flapfoam.io import foam_mesh as fm
from flapfoam.models import wing_geometry as geo
from flapfoam.harness.checklist import Checks
from flapfoam.io.tables import time_value

TARGETS = {"coarse": 71e3, "medium": 214e3, "fine": 501e3, "finePlus": 808e3}
TINY_MAX = 30000
COUNT_TOL = 0.15
AREA_TOL = 0.02

CALCULATED, INTERPOLATED, HOLE = 0, 1, 2


def check_cells(pm, level, report, res):
    """Cells per zone and in total against the level's target."""
    n_cells = fm.read_n_cells(os.path.join(pm, "owner"))
    zones = fm.read_zone_sizes(os.path.join(pm, "cellZones"))
    res.update(n_cells=n_cells, zones=zones)
    print("cells: total %d" % n_cells + "".join(
        ", %s %d (%.1f %%)" % (z, n, 100.0*n/n_cells)
        for z, n in zones.items()))
    report(set(zones) == {"background", "wing"}
           and sum(zones.values()) == n_cells,
           "cellZones background + wing cover the mesh (%s)"
           % ", ".join(zones))
    if level == "tiny":
        report(n_cells <= TINY_MAX, "tiny: %d cells <= %d" % (n_cells, TINY_MAX))
    elif level in TARGETS:
        tgt = TARGETS[level]
        err = n_cells/tgt - 1
        res["countError"] = err
        report(abs(err) <= COUNT_TOL, "%s: %d cells, target %d (%+.1f %%, "
               "tolerance %.0f %%)" % (level, n_cells, tgt, 100*err,
                                       100*COUNT_TOL))


def check_wing_area(pm, bnd, gen, report, res):
    """The wing patch's area against the analytic one, and its breakdown
    in the wing frame (pose of gen, meshGen.json)."""
    pts = fm.read_points(os.path.join(pm, "points"))
    offs, verts = fm.read_faces(os.path.join(pm, "faces"))
    w = bnd["wing"]
    faces = np.arange(w["startFace"], w["startFace"] + w["nFaces"])
    Sf = fm.face_areas_vec(pts, offs, verts, faces)
    mag_sf = np.linalg.norm(Sf, axis=1)
    area = float(mag_sf.sum())
    exact = geo.wing_area()
    err = area/exact - 1
    res.update(wing_area=area, wingAreaAnalytic=exact, wingAreaError=err,
               wingFaces=int(w["nFaces"]))
    report(abs(err) <= AREA_TOL,
           "wing patch area %.6e m^2, analytic %.6e m^2 (%+.3f %%, "
           "tolerance %.0f %%; %d faces)"
           % (area, exact, 100*err, 100*AREA_TOL, w["nFaces"]))

    # breakdown in the wing frame: top + bottom (2 S) and the edge band
    pose = {}
    if os.path.exists(gen):
        with open(gen) as fh:
            pose = json.load(fh).get("pose", {})
    Rpose = geo.pose_matrix(pose.get("phiDeg", 0.0), pose.get("alphaDeg", 0.0))
    nz = np.abs((Sf @ Rpose)[:, 2])/mag_sf      # |n . z_wing|
    flat = float(mag_sf[nz > 0.5].sum())
    band = area - flat
    flat_exact = 2*geo.planform_area()
    band_exact = exact - flat_exact
    res.update(topBottomArea=flat, topBottomAnalytic=flat_exact,
               edgeArea=band, edgeAnalytic=band_exact)
    print("     top + bottom %.6e m^2 (2 S = %.6e, %+.3f %%), edge band "
          "%.6e m^2 (t (P/2 + c_r) = %.6e, %+.3f %%)" % (
              flat, flat_exact, 100*(flat/flat_exact - 1), band, band_exact,
              100*(band/band_exact - 1)))


def mesh_check(argv=None):
    """scripts/meshCheck.py: the mesh checks (see the module's doc)."""
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

    report = Checks()
    res = {"level": level}

    check_cells(pm, level, report, res)
    bnd = fm.read_boundary(os.path.join(pm, "boundary"))
    expect = {"wing": "wall", "oversetPatch": "overset", "farField": "patch"}
    report(all(bnd.get(p, {}).get("type") == t for p, t in expect.items())
           and set(bnd) == set(expect),
           "patches %s" % ", ".join("%s(%s)" % (p, d["type"])
                                     for p, d in bnd.items()))

    check_wing_area(pm, bnd, gen, report, res)
    return report.finish(args.json, res)


# --------------------------------------------------------------------------
# The orphan check

def cell_centres_approx(points, mesh, n_cells):
    """Cell centres as the average of the face centres (good enough to
    measure distances of cells to the wing); mesh: the faces (offs, verts)
    and their owner and neighbour."""
    offs, verts = mesh.offs, mesh.verts
    owner, neighbour = mesh.owner, mesh.neighbour
    sizes = offs[1:] - offs[:-1]
    fc = np.zeros((len(sizes), 3))
    for n in np.unique(sizes):
        sel = np.where(sizes == n)[0]
        idx = offs[sel][:, None] + np.arange(n)[None, :]
        fc[sel] = points[verts[idx]].mean(axis=1)
    acc = np.zeros((n_cells, 3))
    cnt = np.zeros(n_cells)
    np.add.at(acc, owner, fc)
    np.add.at(cnt, owner, 1)
    n_int = len(neighbour)
    np.add.at(acc, neighbour, fc[:n_int])
    np.add.at(cnt, neighbour, 1)
    return acc/cnt[:, None], fc


def rigid_fit(X, Y):
    """R, T minimising |R X + T - Y| (Kabsch), X, Y: (n, 3)."""
    cx, cy = X.mean(axis=0), Y.mean(axis=0)
    H = (X - cx).T @ (Y - cy)
    U, _, Vt = np.linalg.svd(H)
    d = np.sign(np.linalg.det(Vt.T @ U.T))
    R = Vt.T @ np.diag([1.0, 1.0, d]) @ U.T
    return R, cy - R @ cx


def planform_distance(p):
    """Distance of points p (m, 2) to the plate's planform (0 inside)."""
    tau = np.linspace(0.0, np.pi, 4001)
    poly = np.concatenate([geo.edge_point(tau), geo.edge_point([0.0])])
    a, b = poly[:-1], poly[1:]
    ab = b - a
    ap = p[:, None, :] - a[None, :, :]
    t = np.clip((ap*ab).sum(-1)/(ab*ab).sum(-1), 0.0, 1.0)
    dist = np.linalg.norm(ap - t[..., None]*ab, axis=-1).min(axis=1)
    inside = ((p[:, 0]/geo.A)**2 + ((p[:, 1] - geo.R0)/geo.R)**2 <= 1.0) \
        & (p[:, 1] >= geo.R0)
    return np.where(inside, 0.0, dist)


def mesh_at(case, time):
    """polyMesh of a time (moving mesh: points in <time>/polyMesh)."""
    pm = os.path.join(case, "constant", "polyMesh")
    tp = os.path.join(case, time, "polyMesh", "points")
    pts = fm.read_points(tp if (os.path.exists(tp) or os.path.exists(tp + ".gz"))
                        else os.path.join(pm, "points"))
    return pts


def written_times(case):
    """The time folders > 0 holding cellTypes, in order."""
    times = []
    for d in glob.glob(os.path.join(case, "[0-9]*")):
        name = os.path.basename(d)
        if time_value(name, 0.0) > 0 and (
                glob.glob(os.path.join(d, "cellTypes*"))):
            times.append(name)
    times.sort(key=float)
    return times


@dataclass
class MeshAddressing:
    """A polyMesh's faces (offsets offs and vertices verts), points as
    generated (pts0), owner, neighbour and cell count, the wing patch's
    points and the overset patch's cells."""
    offs: object
    verts: object
    pts0: object
    owner: object
    neighbour: object
    n_cells: int
    wing_points: object
    ov_cells: object


def mesh_addressing(case):
    """Faces, cells and patches of the case's polyMesh, the points as
    generated, the wing patch's points and the overset patch's cells."""
    pm = os.path.join(case, "constant", "polyMesh")
    offs, verts = fm.read_faces(os.path.join(pm, "faces"))
    # the mesh as generated (pose of meshGen.json): points0 when the mesh was
    # moved to the start state of the motion (eABAInitialMesh)
    p0 = os.path.join(pm, "points0")
    pts0 = fm.read_points(p0 if (os.path.exists(p0) or os.path.exists(p0 + ".gz"))
                         else os.path.join(pm, "points"))
    owner = fm.read_labels(os.path.join(pm, "owner"))
    neighbour = fm.read_labels(os.path.join(pm, "neighbour"))
    n_cells = fm.read_n_cells(os.path.join(pm, "owner"))
    bnd = fm.read_boundary(os.path.join(pm, "boundary"))
    w, o = bnd["wing"], bnd["oversetPatch"]
    wing_faces = np.arange(w["startFace"], w["startFace"] + w["nFaces"])
    wing_points = np.unique(np.concatenate(
        [verts[offs[f]:offs[f + 1]] for f in wing_faces]))
    ov_cells = np.unique(owner[o["startFace"]:o["startFace"] + o["nFaces"]])
    return MeshAddressing(offs, verts, pts0, owner, neighbour, n_cells,
                          wing_points, ov_cells)


def hole_clearance(x0, margin, h):
    """Background holes x0 (the component's frame at phi = alpha = 0):
    how many lie outside the component, their smallest clearance to its
    boundary and the farthest from the plate (in h)."""
    d_plan = planform_distance(x0[:, :2])
    z_clear = 0.5*geo.THICKNESS + margin - np.abs(x0[:, 2])
    clear = np.minimum(margin - d_plan, z_clear)
    outside = int(np.sum(clear < 0))
    clearance = float(clear.min())/h
    d_wall = np.hypot(d_plan, np.maximum(
        np.abs(x0[:, 2]) - 0.5*geo.THICKNESS, 0.0))
    return outside, clearance, float(d_wall.max())/h


def check_time(case, t, m, gen):
    """The cell types and orphans of one written time: the results."""
    h = gen["background"]["h"]
    margin = gen["component"]["margin"]
    Rgen = geo.pose_matrix(gen["pose"]["phiDeg"], gen["pose"]["alphaDeg"])
    n_cells = m.n_cells
    types = np.rint(fm.read_scalar_field(
        os.path.join(case, t, "cellTypes"))).astype(int)
    zone = np.rint(fm.read_scalar_field(
        os.path.join(case, t, "zoneID"))).astype(int)
    if np.isscalar(types) or len(types) != n_cells:
        types = np.full(n_cells, int(types)) if np.isscalar(types) \
            else types
    pts = mesh_at(case, t)
    cc, fc = cell_centres_approx(pts, m, n_cells)

    res = {"time": t}
    for z, name in ((0, "background"), (1, "wing")):
        sel = zone == z
        res[name] = {k: int(np.sum(types[sel] == v)) for k, v in
                     (("calculated", CALCULATED),
                      ("interpolated", INTERPOLATED), ("hole", HOLE))}
    wing_orphans = int(np.sum((zone == 1) & (types == HOLE)))
    ov_not_interp = int(np.sum(types[m.ov_cells] != INTERPOLATED))

    # background holes in the component's frame at phi = alpha = 0
    R, T = rigid_fit(m.pts0[m.wing_points], pts[m.wing_points])
    bg_holes = np.where((zone == 0) & (types == HOLE))[0]
    outside = 0
    clearance = dmax = float("nan")
    if len(bg_holes):
        x0 = ((cc[bg_holes] - T) @ R) @ Rgen   # R^T, then Rgen^T
        outside, clearance, dmax = hole_clearance(x0, margin, h)
    res.update(wingOrphans=wing_orphans, backgroundOrphans=outside,
               oversetAcceptorsNotInterpolated=ov_not_interp,
               minHoleClearance_h=clearance, maxHoleDistance_h=dmax,
               h=h)
    return res


def overset_check(argv=None):
    """scripts/oversetCheck.py: the orphan check (see the module's doc)."""
    ap = argparse.ArgumentParser()
    ap.add_argument("-case", default=".")
    ap.add_argument("-time", nargs="*", default=None)
    ap.add_argument("-json", default=None)
    args = ap.parse_args(argv)

    case = args.case
    with open(os.path.join(case, "mesh", "meshGen.json")) as fh:
        gen = json.load(fh)
    times = written_times(case) if args.time is None else args.time
    if not times:
        print("FAIL no time directory with cellTypes in %s" % case)
        return 1
    m = mesh_addressing(case)

    report = Checks()
    results = []
    for t in times:
        res = check_time(case, t, m, gen)
        results.append(res)
        report(res["wingOrphans"] == 0 and res["backgroundOrphans"] == 0
               and res["oversetAcceptorsNotInterpolated"] == 0,
               "time %s: orphans: wing %d, background %d (holes outside "
               "the component); overset acceptors not interpolated %d; "
               "background holes: farthest %.2f h from the plate, clearance "
               "to the overset boundary >= %.2f h (h = %.3g m)" % (
                   t, res["wingOrphans"], res["backgroundOrphans"],
                   res["oversetAcceptorsNotInterpolated"],
                   res["maxHoleDistance_h"], res["minHoleClearance_h"],
                   res["h"]))
        for name in ("background", "wing"):
            print("    %-10s calculated %8d  interpolated %7d  hole %7d" % (
                name, res[name]["calculated"], res[name]["interpolated"],
                res[name]["hole"]))
    return report.finish(args.json, results)
