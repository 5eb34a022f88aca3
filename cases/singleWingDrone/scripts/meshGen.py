#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Single-wing drone overset mesh generator (flapFoam, cases/singleWingDrone).

Writes, for one resolution level, the dictionaries of the two component
meshes that scripts/makeMesh turns into the overset mesh:

  <out>/wing/system/blockMeshDict         wing component (cellZone "wing")
  <out>/background/system/blockMeshDict   background cube (cellZone
                                          "background")
  <out>/background/system/topoSetDict.refine<i>  refinement regions along the
                                          wing path, one per refinement pass
                                          (refineHexMesh, 2x2x2 splitting)
  <out>/meshGen.json                      components (merge order), parameters,
                                          planned block counts, analytic wing
                                          area

Usage:
  meshGen.py <level> [-o DIR] [--phi DEG] [--alpha DEG]
  meshGen.py --list

Wing component ("box around a thin box", O-type): the plate |z| <= t/2 with
the semi-elliptical planform is the hole of a block-structured mesh whose
outer boundary lies at the distance `margin` from the plate everywhere (in
the planform: the offset curve of the half ellipse and of the root edge;
along z: the planes z = +-(t/2 + margin)).  Planform blocks:

        ringTp         (outer)
      P2 ---- P1
   ringL| Tp |ringT     P1, P2: corners on the edge at tau2 and pi - tau2
     |  Q3--Q2  |       Q2, Q3: core corners, inwards from P1, P2 (diagBlend)
     | L | C | T |      core sides: x = +-f c(r)/2 (f = coreFrac)
    E0--Q0--Q1--E5      root edge y = R0
   rootL|rootC|rootT    (outer, offset of the root edge and corner arcs)

each extruded in three layers along z: below the wing, the wing level
(|z| <= t/2: only the ring and root blocks, the plate is the hole) and above.
All wall-adjacent spacings are set explicitly (blockMesh edgeGrading with
multi-section grading reproducing the sizes computed here): ds_z (= t/nT)
normal to the top and bottom surfaces, dsE normal to the plate edge and
tangentially at the edge, and the cells grow geometrically (ratio <= q) to
at most h, the background cell size along the wing path, at the overset
boundary.

Background: cube of side 20 cbar centred on the origin (flapping axis at
the stroke plane), uniform N0^3 hex cells, refined nRef times (refineHexMesh,
2:1 balanced) in nested regions that contain the volume swept by the wing
component for |phi| <= 75 deg and |alpha| <= 45 deg (docs/paper.md, Table 1),
so that the component's outer boundary always lies in cells of size
h = 20 cbar/(N0 2^nRef).

Units: metres.  Python: /usr/bin/python3 (numpy).
"""

import argparse
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import wingGeometry as geo  # noqa: E402


# --------------------------------------------------------------------------
# Resolution levels
#
# nS, nL, nC : cells along the span, across each edge strip (leading/trailing
#              edge side of the planform) and across the core (chordwise)
# nT         : cells across the plate thickness (wing level), ds_z = t/nT
# dsE        : first cell size at the plate edge (in-plane) [m]
# q          : maximum growth ratio of the cell sizes away from the plate
# N0, nRef   : background base cells per cube side, refinement passes:
#              h = 20 cbar/(N0 2^nRef) along the wing path; the component's
#              cells grow to (at most) h at its overset boundary
# margin     : (optional) the component's margin instead of COMPONENT's.
#              tiny: 1.0 cbar (29.7k cells).  With 0.8 cbar the tiny mesh
#              failed at t = 0.0062 s of a cycle (Allrun -level tiny
#              -motionOnly): the background's 4.7 mm cells next to the
#              plate, cut by its voxels, reached the component's outer
#              cells, one of them found no donor and the fringe walk turned
#              the wing zone into holes; coarse (3.1 mm) passes the cycle
#              with 0.8 cbar
# --------------------------------------------------------------------------
LEVELS = {
    "tiny":     dict(nS=12, nL=3, nC=3, nT=2, dsE=0.7e-3, q=1.4,
                     N0=16, nRef=2, nBuffer=1, margin=1.0*geo.CBAR),
    "coarse":   dict(nS=24, nL=5, nC=5, nT=2, dsE=0.4e-3, q=1.25,
                     N0=12, nRef=3),
    "medium":   dict(nS=32, nL=7, nC=7, nT=3, dsE=0.3e-3, q=1.2,
                     N0=19, nRef=3),
    "fine":     dict(nS=44, nL=9, nC=9, nT=4, dsE=0.2e-3, q=1.16,
                     N0=26, nRef=3),
    "finePlus": dict(nS=52, nL=11, nC=11, nT=5, dsE=0.16e-3, q=1.14,
                     N0=31, nRef=3),
}

# Topology and extent of the wing component
COMPONENT = dict(
    margin=0.8*geo.CBAR,    # distance plate -> overset boundary [m]
    tau2=math.radians(68),  # tip-block corners P1/P2 at tau2, pi - tau2
    coreFrac=0.45,          # core half width = coreFrac*c(r)/2
    diagBlend=0.6,          # direction P1 -> Q2: blend of the inward normal
                            # at P1 (1) and -y (0), balances the corner angles
    spanFirst=1.5,          # spanwise cells at the root and the tip block:
                            # spanFirst*dsE
    nPoly=120,              # points per polyLine edge
)

# Background and motion envelope
BACKGROUND = dict(
    side=20*geo.CBAR,       # cube side [m]
    centre=(0.0, 0.0, 0.0),
    phiMax=math.radians(75),    # A_phi
    alphaMax=math.radians(45),  # A_alpha
    nBuffer=2,              # cells of each level between refinement
                            # regions (a level may set its own)
    finalMargin=1,          # cells of size h beyond the swept component
)


# --------------------------------------------------------------------------
# 1-D cell distributions
# --------------------------------------------------------------------------

def sizesGeometric(L, N, d0, d1=None, q=1.2):
    """N cell sizes summing to L: growing from d0 (and, if d1 is given,
    shrinking to d1 at the end) by the ratio q, capped by a uniform size
    Dm found so that the sizes add up to L.  If L is too long for q, q is
    raised; if too short for d0 (d1), all sizes are scaled down."""
    i = np.arange(N, dtype=float)

    def sizes(qq, Dm):
        s = d0*qq**i
        if d1 is not None:
            s = np.minimum(s, d1*qq**(N - 1 - i))
        return np.minimum(s, Dm)

    lo_len = sizes(q, max(d0, d1 or d0)).sum()
    if L <= lo_len:
        s = sizes(q, max(d0, d1 or d0))
        return s*L/s.sum()
    if sizes(q, 1e30).sum() < L:
        qa, qb = q, 4.0
        for _ in range(200):
            qm = 0.5*(qa + qb)
            if sizes(qm, 1e30).sum() < L:
                qa = qm
            else:
                qb = qm
        q = qb
    a, b = max(d0, d1 or d0), L
    for _ in range(200):
        m = 0.5*(a + b)
        if sizes(q, m).sum() < L:
            a = m
        else:
            b = m
    s = sizes(q, b)
    return s*L/s.sum()


def nCellsGrowth(L, d0, dEnd, q):
    """Cells to cover L starting at d0, growing by q up to dEnd, then
    uniform dEnd."""
    n, s, x = 0, d0, 0.0
    while x < L*(1 - 1e-9):
        x += min(s, dEnd)
        s *= q
        n += 1
    return n


def gradingSections(sizes, tol=1e-6):
    """blockMesh multi-grading ((lenFrac cellFrac expansion) ...) that
    reproduces the sizes exactly: runs of constant ratio."""
    sizes = np.asarray(sizes, dtype=float)
    L, N = sizes.sum(), len(sizes)
    secs = []
    start = 0
    while start < N:
        end = start + 1
        if end < N:
            r = sizes[end]/sizes[start]
            end += 1
            while end < N and abs(sizes[end]/sizes[end - 1] - r) < tol*r:
                end += 1
        secs.append((sizes[start:end].sum()/L, (end - start)/N,
                     sizes[end - 1]/sizes[start]))
        start = end
    return secs


def fmtGrading(sizes):
    secs = gradingSections(sizes)
    if len(secs) == 1:
        return "%.10g" % secs[0][2]
    return "(" + " ".join("(%.12g %.12g %.12g)" % s for s in secs) + ")"


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


def curveLength(pts):
    return float(np.sum(np.linalg.norm(np.diff(pts, axis=0), axis=1)))


def ellipseArc(t0, t1, n=4000):
    return geo.edgePoint(np.linspace(t0, t1, n))


def offsetArc(t0, t1, d, n=4000):
    t = np.linspace(t0, t1, n)
    return geo.edgePoint(t) + d*geo.edgeNormal(t)


def circleArc(c, r, a0, a1, n=400, ry=None):
    """Arc of the circle (or, with ry, the ellipse of radii r along x and
    ry along y) about c from angle a0 to a1."""
    a = np.linspace(a0, a1, n)
    ry = r if ry is None else ry
    return np.stack([c[0] + r*np.cos(a), c[1] + ry*np.sin(a)], axis=1)


def line(p0, p1, n=50):
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    s = np.linspace(0, 1, n)[:, None]
    return p0 + s*(p1 - p0)


def coreCurve(f, y1, n=4000):
    """Core side x = f c(r)/2 from the root to y = y1 (x >= 0 branch)."""
    y = np.linspace(geo.R0, y1, n)
    return np.stack([0.5*f*geo.chord(y - geo.R0), y], axis=1)


# --------------------------------------------------------------------------
# Wing component
# --------------------------------------------------------------------------

class BlockMesh:
    """Minimal blockMeshDict writer with edge-wise grading bookkeeping."""

    HEX_FACES = {   # outward oriented (OpenFOAM hex model)
        "x0": (0, 4, 7, 3), "x1": (1, 2, 6, 5),
        "y0": (0, 1, 5, 4), "y1": (3, 7, 6, 2),
        "z0": (0, 3, 2, 1), "z1": (4, 5, 6, 7),
    }
    HEX_EDGES = [(0, 1), (3, 2), (7, 6), (4, 5),
                 (0, 3), (1, 2), (5, 6), (4, 7),
                 (0, 4), (1, 5), (2, 6), (3, 7)]

    def __init__(self):
        self.vertices = []
        self.vindex = {}
        self.edges = {}       # (a, b) -> interior points (3D)
        self.sizes = {}       # (a, b) -> cell sizes a -> b
        self.blocks = []
        self.patches = {}

    def vertex(self, key, p):
        if key not in self.vindex:
            self.vindex[key] = len(self.vertices)
            self.vertices.append(np.asarray(p, dtype=float))
        return self.vindex[key]

    def setSizes(self, a, b, s):
        s = np.asarray(s, dtype=float)
        if (b, a) in self.sizes:
            raise KeyError("edge %s given twice" % ((a, b),))
        self.sizes[(a, b)] = s

    def getSizes(self, a, b):
        if (a, b) in self.sizes:
            return self.sizes[(a, b)]
        return self.sizes[(b, a)][::-1]

    def curved(self, a, b, pts3):
        if (b, a) in self.edges or (a, b) in self.edges:
            return
        self.edges[(a, b)] = np.asarray(pts3, dtype=float)

    def block(self, verts, zone):
        n = [len(self.getSizes(verts[0], verts[1])),
             len(self.getSizes(verts[0], verts[3])),
             len(self.getSizes(verts[0], verts[4]))]
        for k, (i, j) in enumerate(self.HEX_EDGES):
            nn = len(self.getSizes(verts[i], verts[j]))
            if nn != n[k//4]:
                raise ValueError("inconsistent cell count on block %s edge "
                                 "%d: %d vs %d" % (verts, k, nn, n[k//4]))
        self.blocks.append((list(verts), zone, n))
        return len(self.blocks) - 1

    def face(self, patch, blockI, side):
        verts = self.blocks[blockI][0]
        self.patches[patch][1].append(
            tuple(verts[i] for i in self.HEX_FACES[side]))

    def patch(self, name, ptype):
        self.patches[name] = (ptype, [])

    def nCells(self):
        return int(sum(np.prod(b[2]) for b in self.blocks))

    def write(self, path, header=""):
        out = []
        out.append(FOAM_HEADER % ("dictionary", "blockMeshDict"))
        out.append(header)
        out.append("convertToMeters 1;\n\nvertices\n(")
        for i, v in enumerate(self.vertices):
            out.append("    (%.12g %.12g %.12g) // %d" % (v[0], v[1], v[2], i))
        out.append(");\n\nblocks\n(")
        for verts, zone, n in self.blocks:
            gr = [fmtGrading(self.getSizes(verts[i], verts[j]))
                  for i, j in self.HEX_EDGES]
            out.append("    hex (%s) %s (%d %d %d)" % (
                " ".join(map(str, verts)), zone, n[0], n[1], n[2]))
            out.append("    edgeGrading\n    (")
            for g in gr:
                out.append("        " + g)
            out.append("    )")
        out.append(");\n\nedges\n(")
        for (a, b), pts in self.edges.items():
            out.append("    polyLine %d %d\n    (" % (a, b))
            for p in pts:
                out.append("        (%.12g %.12g %.12g)" % tuple(p))
            out.append("    )")
        out.append(");\n\nboundary\n(")
        for name, (ptype, faces) in self.patches.items():
            out.append("    %s\n    {\n        type %s;\n        faces\n"
                       "        (" % (name, ptype))
            for f in faces:
                out.append("            (%d %d %d %d)" % f)
            out.append("        );\n    }")
        out.append(");\n\nmergePatchPairs\n(\n);\n")
        out.append(FOAM_FOOTER)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as fh:
            fh.write("\n".join(out))


FOAM_HEADER = r"""/*--------------------------------*- C++ -*----------------------------------*\
| =========                 |                                                 |
| \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox           |
|  \\    /   O peration     | Version:  v1912                                 |
|   \\  /    A nd           | Website:  www.openfoam.com                      |
|    \\/     M anipulation  |                                                 |
\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //
"""

FOAM_FOOTER = ("// ****************************************************"
               "********************* //\n")


def levelComponent(comp, lev):
    """The component's parameters at a level (its own margin, if any)"""
    return dict(comp, margin=lev.get("margin", comp["margin"]))


def wingPlanform(comp):
    """Planform points (x, y) and curves of the wing component."""
    a, R0 = geo.A, geo.R0
    d = comp["margin"]
    # root side (towards the flapping axis): its own margin if given (the
    # body-wing drone keeps the component outside the body); the root
    # corners are then quarter ellipses
    dr = comp.get("rootMargin") or d
    f = comp["coreFrac"]
    tau2 = comp["tau2"]

    P = {}
    P["E0"] = geo.edgePoint(math.pi)
    P["E5"] = geo.edgePoint(0.0)
    P["P1"] = geo.edgePoint(tau2)
    P["P2"] = geo.edgePoint(math.pi - tau2)
    P["Q0"] = np.array([-f*a, R0])
    P["Q1"] = np.array([f*a, R0])

    # Q2 on the core curve x = f c(r)/2, inwards from P1 along a blend of
    # the inward normal and -y
    n1 = geo.edgeNormal(tau2)
    w = comp["diagBlend"]
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
    P["OP2"] = P["P2"] + d*geo.edgeNormal(math.pi - tau2)

    C = {}   # curved planform edges (a, b) -> dense points a -> b
    C[("E0", "P2")] = ellipseArc(math.pi, math.pi - tau2)
    C[("P2", "P1")] = ellipseArc(math.pi - tau2, tau2)
    C[("E5", "P1")] = ellipseArc(0.0, tau2)
    core = coreCurve(f, P["Q2"][1])
    C[("Q1", "Q2")] = core
    C[("Q0", "Q3")] = core*np.array([-1, 1])
    C[("OE0", "OP2")] = np.concatenate([
        circleArc(P["E0"], d, 1.25*math.pi, math.pi, ry=dr),
        offsetArc(math.pi, math.pi - tau2, d)[1:]])
    C[("OP2", "OP1")] = offsetArc(math.pi - tau2, tau2, d)
    C[("OE5", "OP1")] = np.concatenate([
        circleArc(P["E5"], d, -0.25*math.pi, 0.0, ry=dr),
        offsetArc(0.0, tau2, d)[1:]])
    C[("OE0", "OQ0")] = np.concatenate([
        circleArc(P["E0"], d, 1.25*math.pi, 1.5*math.pi, ry=dr),
        line(P["E0"] + [0, -dr], P["OQ0"])[1:]])
    C[("OQ1", "OE5")] = np.concatenate([
        line(P["OQ1"], P["E5"] + [0, -dr])[:-1],
        circleArc(P["E5"], d, 1.5*math.pi, 1.75*math.pi, ry=dr)])
    for k, pts in C.items():
        for end, name in ((0, k[0]), (-1, k[1])):
            if np.linalg.norm(pts[end] - P[name]) > 1e-9:
                raise RuntimeError("curve %s does not end at %s" % (k, name))
    return P, C


def planformLength(P, C, a, b):
    if (a, b) in C:
        return curveLength(C[(a, b)])
    if (b, a) in C:
        return curveLength(C[(b, a)])
    return float(np.linalg.norm(P[b] - P[a]))


def backgroundCellSize(lev, bg):
    return bg["side"]/(lev["N0"]*2**lev["nRef"])


def wingComponent(lev, comp, pose=(0.0, 0.0)):
    """BlockMesh of the wing component for level parameters lev."""
    t = geo.THICKNESS
    d = comp["margin"]
    q = lev["q"]
    nS, nL, nC, nT = lev["nS"], lev["nL"], lev["nC"], lev["nT"]
    dsZ = t/nT
    dsE = lev["dsE"]
    hOut = backgroundCellSize(lev, BACKGROUND)

    P, C = wingPlanform(comp)
    Lp = lambda a, b: planformLength(P, C, a, b)  # noqa: E731

    # ---- planform edge distributions (a -> b) ----
    S = {}
    # radial: from the plate edge out to the overset boundary
    nR = nCellsGrowth(d, dsE, hOut, q)
    rad = sizesGeometric(d, nR, dsE, q=q)
    for p in ("E0", "Q0", "Q1", "E5", "P1", "P2"):
        S[(p, "O" + p)] = rad
    # across the edge strips (fine at the plate edge)
    for a_, b_ in (("E0", "Q0"), ("P2", "Q3"), ("E5", "Q1"), ("P1", "Q2")):
        S[(a_, b_)] = sizesGeometric(Lp(a_, b_), nL, dsE, q=q)
    # core (chordwise) and tip block along the tip: uniform
    for a_, b_ in (("Q0", "Q1"), ("Q3", "Q2"), ("P2", "P1")):
        S[(a_, b_)] = np.full(nC, Lp(a_, b_)/nC)
    # spanwise: fine at the root, down at the top towards the size of the
    # tip block's cells next to the core (spanFirst*dsE at least: the root
    # and tip cells need not be as fine as the wall-normal spacing)
    dTop = min(S[("P1", "Q2")][-1], S[("P2", "Q3")][-1])
    d0 = comp["spanFirst"]*dsE
    for a_, b_ in (("E0", "P2"), ("Q0", "Q3"), ("Q1", "Q2"), ("E5", "P1")):
        S[(a_, b_)] = sizesGeometric(Lp(a_, b_), nS, d0, max(dTop, d0), q=q)
    # outer edges: same fractions as the inner edge they face
    for (a_, b_), (ia, ib) in {
            ("OE0", "OP2"): ("E0", "P2"), ("OP2", "OP1"): ("P2", "P1"),
            ("OE5", "OP1"): ("E5", "P1"), ("OE0", "OQ0"): ("E0", "Q0"),
            ("OQ0", "OQ1"): ("Q0", "Q1"), ("OQ1", "OE5"): ("Q1", "E5")}.items():
        inner = S[(ia, ib)] if (ia, ib) in S else S[(ib, ia)][::-1]
        S[(a_, b_)] = inner/inner.sum()*Lp(a_, b_)

    # ---- z levels and distributions ----
    nZ = nCellsGrowth(d, dsZ, hOut, q)
    zs = [-(0.5*t + d), -0.5*t, 0.5*t, 0.5*t + d]
    zSizes = [sizesGeometric(d, nZ, dsZ, q=q)[::-1],
              np.full(nT, t/nT),
              sizesGeometric(d, nZ, dsZ, q=q)]

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
            bm.setSizes(V[(a_, iz)], V[(b_, iz)], s)
        for (a_, b_), pts in C.items():
            inner = resample(pts, comp["nPoly"])[1:-1]
            bm.curved(V[(a_, iz)], V[(b_, iz)],
                      [X(p, z) for p in inner])
    for iz in range(3):
        for nme in names:
            bm.setSizes(V[(nme, iz)], V[(nme, iz + 1)], zSizes[iz])

    # planform blocks (counter-clockwise seen from +z)
    quads = {
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
    for k, qd in quads.items():
        xy = np.array([P[n] for n in qd])
        area = 0.5*np.sum(xy[:, 0]*np.roll(xy[:, 1], -1)
                          - np.roll(xy[:, 0], -1)*xy[:, 1])
        if area <= 0:
            raise RuntimeError("block %s is not counter-clockwise" % k)
    inside = ("C", "L", "T", "Tp")
    # faces (hex side) of the plate edge and of the overset boundary
    edgeSide = {"ringL": "x0", "ringTp": "x0", "ringT": "x0",
                "rootL": "y1", "rootC": "y1", "rootT": "y1"}
    outerSide = {"ringL": "x1", "ringTp": "x1", "ringT": "x1",
                 "rootL": "y0", "rootC": "y0", "rootT": "y0"}
    # the overset patch first: v1912 wants the master overset patch to be
    # the first patch of the mesh (the wing mesh is the master of the merge)
    bm.patch("oversetPatch", "overset")
    bm.patch("wing", "wall")
    for iz in range(3):
        for k, qd in quads.items():
            if iz == 1 and k in inside:
                continue
            verts = [V[(n, iz)] for n in qd] + [V[(n, iz + 1)] for n in qd]
            b = bm.block(verts, "wing")
            if iz == 0:
                bm.face("oversetPatch", b, "z0")
                if k in inside:
                    bm.face("wing", b, "z1")
            if iz == 2:
                bm.face("oversetPatch", b, "z1")
                if k in inside:
                    bm.face("wing", b, "z0")
            if k in outerSide:
                bm.face("oversetPatch", b, outerSide[k])
            if iz == 1 and k in edgeSide:
                bm.face("wing", b, edgeSide[k])

    info = dict(nR=nR, nZ=nZ, dsZ=dsZ, dsE=dsE, hOut=hOut,
                radialLast=float(rad[-1]), zLast=float(zSizes[2][-1]),
                spanMax=float(max(S[("E0", "P2")])), dTop=float(dTop),
                points={k: [float(v[0]), float(v[1])] for k, v in P.items()},
                blocks=len(bm.blocks), cellsPlanned=bm.nCells())
    return bm, info


def checkBlockSides(bm):
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
    nBoundary = sum(1 for v in count.values() if v == 1)
    nPatch = sum(len(f) for _, f in bm.patches.values())
    if nBoundary != nPatch:
        raise RuntimeError("%d block boundary faces, %d in patches"
                           % (nBoundary, nPatch))


# --------------------------------------------------------------------------
# Background
# --------------------------------------------------------------------------

def componentOutline(comp, nPer=200):
    """Points on the overset boundary of the wing component at phi = alpha
    = 0 (planform outer contour at z = +-(t/2 + margin)): the extreme points
    of the component under any rotation."""
    P, C = wingPlanform(comp)
    pts = []
    for k in (("OE0", "OP2"), ("OP2", "OP1"), ("OE5", "OP1"),
              ("OE0", "OQ0"), ("OQ1", "OE5")):
        pts.append(resample(C[k], nPer))
    pts.append(line(P["OQ0"], P["OQ1"], 10))
    xy = np.concatenate(pts)
    H = 0.5*geo.THICKNESS + comp["margin"]
    return np.concatenate([
        np.column_stack([xy, np.full(len(xy), z)]) for z in (-H, H)])


def rotY(a):
    return np.array([[math.cos(a), 0, math.sin(a)], [0, 1, 0],
                     [-math.sin(a), 0, math.cos(a)]])


def sweptEnvelope(comp, bg, tilts=(0.0,)):
    """Envelope of the component over |phi| <= phiMax, |alpha| <= alphaMax
    (and a pitch of the stroke plane about y by each angle of tilts: the
    body pitch of the body-wing drone): zMax, rMax (about the z axis), and
    the half-space y >= yA outside the cylinder r <= rB."""
    base = componentOutline(comp)
    pts = []
    for phi in np.linspace(-bg["phiMax"], bg["phiMax"], 61):
        for alpha in np.linspace(-bg["alphaMax"], bg["alphaMax"], 19):
            Rz = np.array([[math.cos(phi), -math.sin(phi), 0],
                           [math.sin(phi), math.cos(phi), 0], [0, 0, 1]])
            for tilt in tilts:
                pts.append(base @ (rotY(tilt) @ Rz @ rotY(alpha)).T)
    pts = np.concatenate(pts)
    r = np.hypot(pts[:, 0], pts[:, 1])
    rMax = float(r.max())
    zMax = float(np.abs(pts[:, 2]).max())
    yA = float(pts[r > 0.5*rMax, 1].min())
    rB = float(r[pts[:, 1] < yA].max()) if np.any(pts[:, 1] < yA) else 0.0
    return dict(rMax=rMax, zMax=zMax, yA=yA, rB=rB)


def backgroundMesh(lev, bg, env):
    side = bg["side"]
    c = np.asarray(bg["centre"], dtype=float)
    N0, nRef = lev["N0"], lev["nRef"]
    h0 = side/N0
    bm = BlockMesh()
    verts = []
    for k, (i, j, l) in enumerate([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                                   (0, 0, 1), (1, 0, 1), (1, 1, 1),
                                   (0, 1, 1)]):
        p = c + side*(np.array([i, j, l]) - 0.5)
        verts.append(bm.vertex(k, p))
    for a_, b_ in BlockMesh.HEX_EDGES:
        if (a_, b_) not in bm.sizes and (b_, a_) not in bm.sizes:
            bm.setSizes(verts[a_], verts[b_], np.full(N0, h0))
    b = bm.block(verts, "background")
    bm.patch("farField", "patch")
    for side_ in BlockMesh.HEX_FACES:
        bm.face("farField", b, side_)

    # nested refinement regions, finest last
    h = [h0/2**j for j in range(nRef + 1)]     # h[j]: size after pass j
    margins = [0.0]*(nRef + 1)
    # a cell is selected when its centre is in the region: half a cell of
    # the pass's input size added to each margin
    m = bg["finalMargin"]*h[nRef] + 0.5*h[nRef - 1]
    margins[nRef] = m
    for j in range(nRef - 1, 0, -1):
        m = m + lev.get("nBuffer", bg["nBuffer"])*h[j] \
            + 0.5*h[j - 1]
        margins[j] = m
    regions = []
    for j in range(1, nRef + 1):
        m = margins[j]
        regions.append(dict(
            rA=env["rMax"] + m, z=env["zMax"] + m, yA=env["yA"] - m,
            rB=env["rB"] + m if env["rB"] > 0 else 0.0))
    info = dict(h0=h0, h=h[nRef], nRef=nRef, N0=N0, margins=margins[1:],
                regions=regions, envelope=env)
    return bm, info


def topoSetRefine(region, centre, extra=()):
    """topoSetDict of a refinement pass: the region's cylinders, and the
    extra actions (action, source, body) after them."""
    c = centre
    big = 10.0
    acts = [
        ("new", "cylinderToCell",
         "p1 (%.9g %.9g %.9g);\n        p2 (%.9g %.9g %.9g);\n"
         "        radius %.9g;" % (c[0], c[1], c[2] - region["z"],
                                   c[0], c[1], c[2] + region["z"],
                                   region["rA"])),
        ("subtract", "boxToCell",
         "box (%.9g %.9g %.9g) (%.9g %.9g %.9g);"
         % (-big, -big, -big, big, region["yA"], big)),
    ]
    if region["rB"] > 0:
        acts.append(
            ("add", "cylinderToCell",
             "p1 (%.9g %.9g %.9g);\n        p2 (%.9g %.9g %.9g);\n"
             "        radius %.9g;" % (c[0], c[1], c[2] - region["z"],
                                       c[0], c[1], c[2] + region["z"],
                                       region["rB"])))
    acts.extend(extra)
    out = [FOAM_HEADER % ("dictionary", "topoSetDict"),
           "// Refinement region: the volume swept by the wing component "
           "plus a margin\n", "actions\n("]
    for action, source, body in acts:
        out.append("    {\n        name    refine;\n        type    cellSet;"
                   "\n        action  %s;\n        source  %s;\n        %s\n"
                   "    }" % (action, source, body))
    out.append(");\n")
    out.append(FOAM_FOOTER)
    return "\n".join(out)


MINIMAL_CONTROLDICT = FOAM_HEADER % ("dictionary", "controlDict") + """
libs            ("liboverset.so");

application     blockMesh;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         1;
deltaT          1;
writeControl    timeStep;
writeInterval   1;
writeFormat     ascii;
writePrecision  12;
writeCompression off;
timeFormat      general;
timePrecision   6;
runTimeModifiable false;

""" + FOAM_FOOTER

MINIMAL_FVSCHEMES = FOAM_HEADER % ("dictionary", "fvSchemes") + """
ddtSchemes { default none; }
gradSchemes { default Gauss linear; }
divSchemes { default none; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }

""" + FOAM_FOOTER

MINIMAL_FVSOLUTION = FOAM_HEADER % ("dictionary", "fvSolution") + """
""" + FOAM_FOOTER


def writeCase(path, bm, header, extra=None):
    sysdir = os.path.join(path, "system")
    os.makedirs(sysdir, exist_ok=True)
    bm.write(os.path.join(sysdir, "blockMeshDict"), header)
    for name, text in (("controlDict", MINIMAL_CONTROLDICT),
                       ("fvSchemes", MINIMAL_FVSCHEMES),
                       ("fvSolution", MINIMAL_FVSOLUTION)):
        with open(os.path.join(sysdir, name), "w") as fh:
            fh.write(text)
    for name, text in (extra or {}).items():
        with open(os.path.join(sysdir, name), "w") as fh:
            fh.write(text)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("level", nargs="?", choices=list(LEVELS))
    ap.add_argument("-o", "--output", default="mesh",
                    help="output folder (default: mesh)")
    ap.add_argument("--phi", type=float, default=0.0,
                    help="initial flapping angle of the wing [deg]")
    ap.add_argument("--alpha", type=float, default=0.0,
                    help="initial pitching angle of the wing [deg]")
    ap.add_argument("--list", action="store_true",
                    help="print the planned cell counts of every level")
    args = ap.parse_args(argv)

    if args.list:
        for name, lev in LEVELS.items():
            comp = levelComponent(COMPONENT, lev)
            bm, info = wingComponent(lev, comp)
            _, binfo = backgroundMesh(lev, BACKGROUND,
                                      sweptEnvelope(comp, BACKGROUND))
            print("%-9s wing blocks %7d cells (nR %d nZ %d)  background "
                  "h %.2f mm" % (name, info["cellsPlanned"], info["nR"],
                                 info["nZ"], 1e3*binfo["h"]))
        return 0
    if args.level is None:
        ap.error("level required")

    lev = LEVELS[args.level]
    comp = levelComponent(COMPONENT, lev)
    pose = (math.radians(args.phi), math.radians(args.alpha))
    wbm, winfo = wingComponent(lev, comp, pose)
    checkBlockSides(wbm)
    env = sweptEnvelope(comp, BACKGROUND)
    bbm, binfo = backgroundMesh(lev, BACKGROUND, env)

    hdr = ("// Generated by scripts/meshGen.py %s: do not edit\n"
           % " ".join(sys.argv[1:] if argv is None else argv))
    writeCase(os.path.join(args.output, "wing"), wbm,
              hdr + "// Single-wing drone: wing component (O-type, overset)"
              "\n\n")
    extra = {"topoSetDict.refine%d" % (j + 1):
             topoSetRefine(r, BACKGROUND["centre"])
             for j, r in enumerate(binfo["regions"])}
    writeCase(os.path.join(args.output, "background"), bbm,
              hdr + "// Single-wing drone: background cube\n\n", extra)

    # components in merge order (scripts/makeOversetMesh): the wing is the
    # master, so that its overset patch becomes the first patch
    summary = dict(components=[dict(name="wing"), dict(name="background")],
                   level=args.level, levelParameters=lev,
                   pose=dict(phiDeg=args.phi, alphaDeg=args.alpha),
                   geometry=geo.summary(),
                   component=comp,
                   wing=winfo, background=binfo,
                   backgroundParameters={k: v for k, v in BACKGROUND.items()})
    with open(os.path.join(args.output, "meshGen.json"), "w") as fh:
        json.dump(summary, fh, indent=2, default=float)
    print("meshGen: level %s: wing %d cells in %d blocks, background "
          "%d^3 cells refined %d times (h = %.3g m)"
          % (args.level, winfo["cellsPlanned"], winfo["blocks"], lev["N0"],
             lev["nRef"], binfo["h"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
