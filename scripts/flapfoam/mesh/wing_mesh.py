# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The wing component of the drone meshes ("box around a thin box", O-type,
see the single-wing drone's scripts/meshGen.py): its resolution levels and
topology, the planform curves, the blocks, and the envelope it sweeps over
the stroke.  numpy only.
"""

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np

from flapfoam.models import wing_geometry as geo
from flapfoam.mesh.background_mesh import BACKGROUND, background_cell_size
from flapfoam.mesh.block_mesh import (BlockMesh, n_cells_growth, sizes_geometric)


# --------------------------------------------------------------------------
# Resolution levels (in meshGen.json and the docs by their camelCase names:
# nS, nL, nC, nT, dsE, q, N0, nRef, nBuffer, margin)
#
# n_s, n_l, n_c : cells along the span, across each edge strip
#              (leading/trailing edge side of the planform) and across the
#              core (chordwise)
# n_t        : cells across the plate thickness (wing level), ds_z = t/n_t
# ds_e       : first cell size at the plate edge (in-plane) [m]
# q          : maximum growth ratio of the cell sizes away from the plate
# n0, n_ref  : background base cells per cube side, refinement passes:
#              h = 20 cbar/(n0 2^n_ref) along the wing path; the component's
#              cells grow to (at most) h at its overset boundary
# n_buffer   : (optional) the background's cells between refinement regions
#              instead of BACKGROUND's
# margin     : (optional) the component's margin instead of COMPONENT's
#              (tiny: 1.0 cbar; with 0.8 cbar tiny failed a whole cycle of
#              Allrun -motionOnly; cases/bodyWingDrone/README.md, "Whole
#              cycles")
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class MeshLevel:
    """A resolution level (the names above; margin and n_buffer None: the
    component's and the background's own)."""
    n_s: int
    n_l: int
    n_c: int
    n_t: int
    ds_e: float
    q: float
    n0: int = field(metadata={"key": "N0"})
    n_ref: int
    n_buffer: int = None
    margin: float = None


LEVELS = {
    "tiny":     MeshLevel(n_s=12, n_l=3, n_c=3, n_t=2, ds_e=0.7e-3, q=1.4,
                          n0=16, n_ref=2, n_buffer=1, margin=1.0*geo.CBAR),
    "coarse":   MeshLevel(n_s=24, n_l=5, n_c=5, n_t=2, ds_e=0.4e-3, q=1.25,
                          n0=12, n_ref=3),
    "medium":   MeshLevel(n_s=32, n_l=7, n_c=7, n_t=3, ds_e=0.3e-3, q=1.2,
                          n0=19, n_ref=3),
    "fine":     MeshLevel(n_s=44, n_l=9, n_c=9, n_t=4, ds_e=0.2e-3, q=1.16,
                          n0=26, n_ref=3),
    "finePlus": MeshLevel(n_s=52, n_l=11, n_c=11, n_t=5, ds_e=0.16e-3,
                          q=1.14, n0=31, n_ref=3),
}


@dataclass(frozen=True)
class Component:
    """Topology and extent of the wing component."""
    margin: float           # distance plate -> overset boundary [m]
    tau2: float             # tip-block corners P1/P2 at tau2, pi - tau2
    core_frac: float        # core half width = core_frac*c(r)/2
    diag_blend: float       # direction P1 -> Q2: blend of the inward normal
                            # at P1 (1) and -y (0), balances the corners
    span_first: float       # spanwise cells at the root and the tip block:
                            # span_first*ds_e
    n_poly: int             # points per polyLine edge
    root_margin: float = None   # the root side's margin (None: margin)


COMPONENT = Component(margin=0.8*geo.CBAR, tau2=math.radians(68),
                      core_frac=0.45, diag_blend=0.6, span_first=1.5,
                      n_poly=120)

# --------------------------------------------------------------------------
# Planform curves (x, y) sampled by arc length
# --------------------------------------------------------------------------

def resample(pts, n):
    """n points equally spaced by arc length along the polyline pts."""
    pts = np.asarray(pts, dtype=float)
    seg = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    s = np.concatenate([[0], np.cumsum(seg)])
    t = np.linspace(0, s[-1], n)
    return np.stack([np.interp(t, s, pts[:, k]) for k in range(2)], axis=1)


def curve_length(pts):
    return float(np.sum(np.linalg.norm(np.diff(pts, axis=0), axis=1)))


def ellipse_arc(t0, t1, n=4000):
    return geo.edge_point(np.linspace(t0, t1, n))


def offset_arc(t0, t1, d, n=4000):
    t = np.linspace(t0, t1, n)
    return geo.edge_point(t) + d*geo.edge_normal(t)


def circle_arc(c, r, a0, a1, ry=None):
    """Arc of the circle (or, with ry, the ellipse of radii r along x and
    ry along y) about c from angle a0 to a1, 400 points."""
    a = np.linspace(a0, a1, 400)
    ry = r if ry is None else ry
    return np.stack([c[0] + r*np.cos(a), c[1] + ry*np.sin(a)], axis=1)


def line(p0, p1, n=50):
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    s = np.linspace(0, 1, n)[:, None]
    return p0 + s*(p1 - p0)


def core_curve(f, y1, n=4000):
    """Core side x = f c(r)/2 from the root to y = y1 (x >= 0 branch)."""
    y = np.linspace(geo.R0, y1, n)
    return np.stack([0.5*f*geo.chord(y - geo.R0), y], axis=1)


# --------------------------------------------------------------------------
# Wing component
# --------------------------------------------------------------------------

def level_component(comp, lev):
    """The component's parameters at a level (its own margin, if any)"""
    return comp if lev.margin is None else \
        dataclasses.replace(comp, margin=lev.margin)


def wing_planform(comp):
    """Planform points (x, y) and curves of the wing component."""
    a, R0 = geo.A, geo.R0
    d = comp.margin
    # root side (towards the flapping axis): its own margin if given (the
    # body-wing drone keeps the component outside the body); the root
    # corners are then quarter ellipses
    dr = comp.root_margin or d
    f = comp.core_frac
    tau2 = comp.tau2

    P = {}
    P["E0"] = geo.edge_point(math.pi)
    P["E5"] = geo.edge_point(0.0)
    P["P1"] = geo.edge_point(tau2)
    P["P2"] = geo.edge_point(math.pi - tau2)
    P["Q0"] = np.array([-f*a, R0])
    P["Q1"] = np.array([f*a, R0])

    # Q2 on the core curve x = f c(r)/2, inwards from P1 along a blend of
    # the inward normal and -y
    n1 = geo.edge_normal(tau2)
    w = comp.diag_blend
    dvec = w*n1 + (1 - w)*np.array([0.0, 1.0])
    dvec /= np.linalg.norm(dvec)
    lo, hi = 0.0, np.linalg.norm(P["P1"] - P["Q1"])
    for _ in range(200):
        s = 0.5*(lo + hi)
        q = P["P1"] - s*dvec
        if q[0] > 0.5*f*geo.chord(q[1] - R0):
            lo = s
        else:
            hi = s
    q = P["P1"] - hi*dvec
    P["Q2"] = np.array([0.5*f*geo.chord(q[1] - R0), q[1]])
    P["Q3"] = np.array([-P["Q2"][0], P["Q2"][1]])

    s2 = 1/math.sqrt(2)
    P["OE0"] = P["E0"] + np.array([-d*s2, -dr*s2])
    P["OE5"] = P["E5"] + np.array([d*s2, -dr*s2])
    P["OQ0"] = np.array([-f*a, R0 - dr])
    P["OQ1"] = np.array([f*a, R0 - dr])
    P["OP1"] = P["P1"] + d*n1
    P["OP2"] = P["P2"] + d*geo.edge_normal(math.pi - tau2)

    C = {}   # curved planform edges (a, b) -> dense points a -> b
    C[("E0", "P2")] = ellipse_arc(math.pi, math.pi - tau2)
    C[("P2", "P1")] = ellipse_arc(math.pi - tau2, tau2)
    C[("E5", "P1")] = ellipse_arc(0.0, tau2)
    core = core_curve(f, P["Q2"][1])
    C[("Q1", "Q2")] = core
    C[("Q0", "Q3")] = core*np.array([-1, 1])
    C[("OE0", "OP2")] = np.concatenate([
        circle_arc(P["E0"], d, 1.25*math.pi, math.pi, ry=dr),
        offset_arc(math.pi, math.pi - tau2, d)[1:]])
    C[("OP2", "OP1")] = offset_arc(math.pi - tau2, tau2, d)
    C[("OE5", "OP1")] = np.concatenate([
        circle_arc(P["E5"], d, -0.25*math.pi, 0.0, ry=dr),
        offset_arc(0.0, tau2, d)[1:]])
    C[("OE0", "OQ0")] = np.concatenate([
        circle_arc(P["E0"], d, 1.25*math.pi, 1.5*math.pi, ry=dr),
        line(P["E0"] + [0, -dr], P["OQ0"])[1:]])
    C[("OQ1", "OE5")] = np.concatenate([
        line(P["OQ1"], P["E5"] + [0, -dr])[:-1],
        circle_arc(P["E5"], d, 1.5*math.pi, 1.75*math.pi, ry=dr)])
    for k, pts in C.items():
        for end, name in ((0, k[0]), (-1, k[1])):
            if np.linalg.norm(pts[end] - P[name]) > 1e-9:
                raise RuntimeError("curve %s does not end at %s" % (k, name))
    return P, C


def planform_length(P, C, a, b):
    if (a, b) in C:
        return curve_length(C[(a, b)])
    if (b, a) in C:
        return curve_length(C[(b, a)])
    return float(np.linalg.norm(P[b] - P[a]))


# Planform blocks (counter-clockwise seen from +z), the plate's (inside:
# not at the wing level, where the plate is the hole) and the hex sides of
# the plate edge and of the overset boundary
QUADS = {
    "C":     ("Q0", "Q1", "Q2", "Q3"),
    "L":     ("E0", "Q0", "Q3", "P2"),
    "T":     ("Q1", "E5", "P1", "Q2"),
    "Tp":    ("Q3", "Q2", "P1", "P2"),
    "ringL": ("P2", "OP2", "OE0", "E0"),
    "ringTp": ("P1", "OP1", "OP2", "P2"),
    "ringT": ("E5", "OE5", "OP1", "P1"),
    "rootL": ("OE0", "OQ0", "Q0", "E0"),
    "rootC": ("OQ0", "OQ1", "Q1", "Q0"),
    "rootT": ("OQ1", "OE5", "E5", "Q1"),
}
INSIDE = ("C", "L", "T", "Tp")
EDGE_SIDE = {"ringL": "x0", "ringTp": "x0", "ringT": "x0",
             "rootL": "y1", "rootC": "y1", "rootT": "y1"}
OUTER_SIDE = {"ringL": "x1", "ringTp": "x1", "ringT": "x1",
              "rootL": "y0", "rootC": "y0", "rootT": "y0"}


def planform_sizes(lev, comp, P, C, h_out):
    """Cell sizes of the planform edges (a, b) -> sizes a -> b, and the
    radial distribution and the top span size dTop."""
    d = comp.margin
    q = lev.q
    n_s, n_l, n_c = lev.n_s, lev.n_l, lev.n_c
    ds_e = lev.ds_e
    Lp = lambda a, b: planform_length(P, C, a, b)  # noqa: E731

    S = {}
    # radial: from the plate edge out to the overset boundary
    n_r = n_cells_growth(d, ds_e, h_out, q)
    rad = sizes_geometric(d, n_r, ds_e, q=q)
    for p in ("E0", "Q0", "Q1", "E5", "P1", "P2"):
        S[(p, "O" + p)] = rad
    # across the edge strips (fine at the plate edge)
    for a_, b_ in (("E0", "Q0"), ("P2", "Q3"), ("E5", "Q1"), ("P1", "Q2")):
        S[(a_, b_)] = sizes_geometric(Lp(a_, b_), n_l, ds_e, q=q)
    # core (chordwise) and tip block along the tip: uniform
    for a_, b_ in (("Q0", "Q1"), ("Q3", "Q2"), ("P2", "P1")):
        S[(a_, b_)] = np.full(n_c, Lp(a_, b_)/n_c)
    # spanwise: fine at the root, down at the top towards the size of the
    # tip block's cells next to the core (spanFirst*dsE at least: the root
    # and tip cells need not be as fine as the wall-normal spacing)
    d_top = min(S[("P1", "Q2")][-1], S[("P2", "Q3")][-1])
    d0 = comp.span_first*ds_e
    for a_, b_ in (("E0", "P2"), ("Q0", "Q3"), ("Q1", "Q2"), ("E5", "P1")):
        S[(a_, b_)] = sizes_geometric(Lp(a_, b_), n_s, d0, max(d_top, d0), q=q)
    # outer edges: same fractions as the inner edge they face
    for (a_, b_), (ia, ib) in {
            ("OE0", "OP2"): ("E0", "P2"), ("OP2", "OP1"): ("P2", "P1"),
            ("OE5", "OP1"): ("E5", "P1"), ("OE0", "OQ0"): ("E0", "Q0"),
            ("OQ0", "OQ1"): ("Q0", "Q1"), ("OQ1", "OE5"): ("Q1", "E5")}.items():
        inner = S[(ia, ib)] if (ia, ib) in S else S[(ib, ia)][::-1]
        S[(a_, b_)] = inner/inner.sum()*Lp(a_, b_)
    return S, rad, d_top


def check_counter_clockwise(P):
    for k, qd in QUADS.items():
        xy = np.array([P[n] for n in qd])
        area = 0.5*np.sum(xy[:, 0]*np.roll(xy[:, 1], -1)
                          - np.roll(xy[:, 0], -1)*xy[:, 1])
        if area <= 0:
            raise RuntimeError("block %s is not counter-clockwise" % k)


def add_blocks(bm, V):
    """The blocks of the three z layers and their patch faces."""
    # the overset patch first: v1912 wants the master overset patch to be
    # the first patch of the mesh (the wing mesh is the master of the merge)
    bm.patch("oversetPatch", "overset")
    bm.patch("wing", "wall")
    for iz in range(3):
        for k, qd in QUADS.items():
            if iz == 1 and k in INSIDE:
                continue
            verts = [V[(n, iz)] for n in qd] + [V[(n, iz + 1)] for n in qd]
            b = bm.block(verts, "wing")
            if iz == 0:
                bm.face("oversetPatch", b, "z0")
                if k in INSIDE:
                    bm.face("wing", b, "z1")
            if iz == 2:
                bm.face("oversetPatch", b, "z1")
                if k in INSIDE:
                    bm.face("wing", b, "z0")
            if k in OUTER_SIDE:
                bm.face("oversetPatch", b, OUTER_SIDE[k])
            if iz == 1 and k in EDGE_SIDE:
                bm.face("wing", b, EDGE_SIDE[k])


def wing_component(lev, comp, pose=(0.0, 0.0)):
    """BlockMesh of the wing component for level parameters lev."""
    t = geo.THICKNESS
    d = comp.margin
    q = lev.q
    n_t = lev.n_t
    ds_z = t/n_t
    ds_e = lev.ds_e
    h_out = background_cell_size(lev, BACKGROUND)

    P, C = wing_planform(comp)
    S, rad, d_top = planform_sizes(lev, comp, P, C, h_out)
    n_r = len(rad)

    # ---- z levels and distributions ----
    n_z = n_cells_growth(d, ds_z, h_out, q)
    zs = [-(0.5*t + d), -0.5*t, 0.5*t, 0.5*t + d]
    z_sizes = [sizes_geometric(d, n_z, ds_z, q=q)[::-1],
              np.full(n_t, t/n_t),
              sizes_geometric(d, n_z, ds_z, q=q)]

    # ---- pose (optional initial flapping/pitching for tests) ----
    phi, alpha = pose
    Rz = np.array([[math.cos(phi), -math.sin(phi), 0],
                   [math.sin(phi), math.cos(phi), 0], [0, 0, 1]])
    Ry = np.array([[math.cos(alpha), 0, math.sin(alpha)], [0, 1, 0],
                   [-math.sin(alpha), 0, math.cos(alpha)]])
    Rot = Rz @ Ry

    def X(p2, z):
        return Rot @ np.array([p2[0], p2[1], z])

    bm = BlockMesh()
    names = list(P.keys())
    V = {}
    for iz, z in enumerate(zs):
        for nme in names:
            V[(nme, iz)] = bm.vertex((nme, iz), X(P[nme], z))

    # planform edges at every z level
    for iz, z in enumerate(zs):
        for (a_, b_), s in S.items():
            bm.set_sizes(V[(a_, iz)], V[(b_, iz)], s)
        for (a_, b_), pts in C.items():
            inner = resample(pts, comp.n_poly)[1:-1]
            bm.curved(V[(a_, iz)], V[(b_, iz)],
                      [X(p, z) for p in inner])
    for iz in range(3):
        for nme in names:
            bm.set_sizes(V[(nme, iz)], V[(nme, iz + 1)], z_sizes[iz])

    check_counter_clockwise(P)
    add_blocks(bm, V)

    info = dict(nR=n_r, nZ=n_z, dsZ=ds_z, dsE=ds_e, hOut=h_out,
                radialLast=float(rad[-1]), zLast=float(z_sizes[2][-1]),
                spanMax=float(max(S[("E0", "P2")])), dTop=float(d_top),
                points={k: [float(v[0]), float(v[1])] for k, v in P.items()},
                blocks=len(bm.blocks), cellsPlanned=bm.n_cells())
    return bm, info


def check_block_sides(bm):
    """Each patch face must be a face of exactly one block: a cheap
    consistency check of the side names used above."""
    count = {}
    for verts, _, _ in bm.blocks:
        for side, f in BlockMesh.HEX_FACES.items():
            key = frozenset(verts[i] for i in f)
            count[key] = count.get(key, 0) + 1
    for name, (_, faces) in bm.patches.items():
        for f in faces:
            if count.get(frozenset(f), 0) != 1:
                raise RuntimeError("patch %s face %s is not a boundary face"
                                   % (name, f))
    n_boundary = sum(1 for v in count.values() if v == 1)
    n_patch = sum(len(f) for _, f in bm.patches.values())
    if n_boundary != n_patch:
        raise RuntimeError("%d block boundary faces, %d in patches"
                           % (n_boundary, n_patch))


# --------------------------------------------------------------------------
# Envelope of the motion
# --------------------------------------------------------------------------

def component_outline(comp, n_per=200):
    """Points on the overset boundary of the wing component at phi = alpha
    = 0 (planform outer contour at z = +-(t/2 + margin)): the extreme points
    of the component under any rotation."""
    P, C = wing_planform(comp)
    pts = []
    for k in (("OE0", "OP2"), ("OP2", "OP1"), ("OE5", "OP1"),
              ("OE0", "OQ0"), ("OQ1", "OE5")):
        pts.append(resample(C[k], n_per))
    pts.append(line(P["OQ0"], P["OQ1"], 10))
    xy = np.concatenate(pts)
    H = 0.5*geo.THICKNESS + comp.margin
    return np.concatenate([
        np.column_stack([xy, np.full(len(xy), z)]) for z in (-H, H)])


def rot_y(a):
    return np.array([[math.cos(a), 0, math.sin(a)], [0, 1, 0],
                     [-math.sin(a), 0, math.cos(a)]])


def swept_envelope(comp, bg, tilts=(0.0,)):
    """Envelope of the component over |phi| <= phiMax, |alpha| <= alphaMax
    (and a pitch of the stroke plane about y by each angle of tilts: the
    body pitch of the body-wing drone): zMax, rMax (about the z axis), and
    the half-space y >= yA outside the cylinder r <= rB."""
    base = component_outline(comp)
    pts = []
    for phi in np.linspace(-bg.phi_max, bg.phi_max, 61):
        for alpha in np.linspace(-bg.alpha_max, bg.alpha_max, 19):
            Rz = np.array([[math.cos(phi), -math.sin(phi), 0],
                           [math.sin(phi), math.cos(phi), 0], [0, 0, 1]])
            for tilt in tilts:
                pts.append(base @ (rot_y(tilt) @ Rz @ rot_y(alpha)).T)
    pts = np.concatenate(pts)
    r = np.hypot(pts[:, 0], pts[:, 1])
    r_max = float(r.max())
    z_max = float(np.abs(pts[:, 2]).max())
    y_a = float(pts[r > 0.5*r_max, 1].min())
    r_b = float(r[pts[:, 1] < y_a].max()) if np.any(pts[:, 1] < y_a) else 0.0
    return dict(rMax=r_max, zMax=z_max, yA=y_a, rB=r_b)


