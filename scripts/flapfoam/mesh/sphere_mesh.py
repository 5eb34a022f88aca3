# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The body component of the drones with a sphere (cases/bodyWingDrone,
cases/twoWingDrone): a spherical shell around the sphere of radius one
chord (cellZone "body"): the body-wing drone's (SHELL) with its
scripts/sphereMesh.py (main), another case's Shell through the functions:

    sphereMesh.py <level> [-o FILE]         the blockMeshDict
    sphereMesh.py -map POINTS [-centre X Y Z]
                                            map blockMesh's points onto
                                            the spheres (ascii points file)
    sphereMesh.py -list

Six blocks of a cubed sphere between the body surface (radius R1 = cbar,
patch "body", wall) and the overset boundary (radius R2 = R1 + margin, patch
"oversetPatch", overset).  blockMesh makes the shell between the cubes of
half side 1 and 2 (n x n cells on each face, nR along the rays from the
origin, graded geometrically from the wall spacing dsW); -map moves each
point along its ray to the radius R1 + (rho - 1)(R2 - R1), rho its max-norm
(a gnomonic cubed sphere: the faces lie exactly on the spheres).  blockMesh's
own projection onto spheres is not used: with a hollow shell its interior
points come from the flat cube faces, which crushes the wall cells.

Units: metres.  Python: /usr/bin/python3.  Also the refinement of the
background around the body (refine_actions).
"""

import argparse
import math
import os
import sys
from dataclasses import dataclass

from flapfoam.mesh.poly_mesh import rewrite_points

CBAR = 0.015                # mean chord [m] (docs/paper.md, Table 1)
R1 = CBAR                   # body radius: one chord
MARGIN = 0.8*CBAR           # body -> overset boundary, as the wing's [m]

# n: cells along a cube edge (4 n around a great circle); n_r: radial cells;
# ds_w: first cell at the body surface [m].  Fewer cells at tiny (n = 6,
# or n = 10 with nR = 10) failed a whole cycle of Allrun -motionOnly:
# README.md, "Whole cycles"
@dataclass(frozen=True)
class SphereLevel:
    """A level of the body component (n, nR, dsW in meshGen.json)."""
    n: int
    n_r: int
    ds_w: float


LEVELS = {
    "tiny":     SphereLevel(n=14, n_r=12, ds_w=0.6e-3),
    "coarse":   SphereLevel(n=14, n_r=14, ds_w=0.35e-3),
    "medium":   SphereLevel(n=20, n_r=18, ds_w=0.25e-3),
    "fine":     SphereLevel(n=28, n_r=24, ds_w=0.17e-3),
    "finePlus": SphereLevel(n=34, n_r=28, ds_w=0.14e-3),
}


def expansion(L, n, d0):
    """Ratio last/first of n geometric cells of total length L starting at
    d0 (bisection on the growth factor)."""
    if n == 1:
        return 1.0
    lo, hi = 1e-6, 10.0

    def total(g):
        return d0*n if abs(g - 1) < 1e-12 else d0*(g**n - 1)/(g - 1)
    for _ in range(200):
        mid = 0.5*(lo + hi)
        if total(mid) > L:
            hi = mid
        else:
            lo = mid
    g = 0.5*(lo + hi)
    return g**(n - 1)


def block_mesh_dict(level, margin=MARGIN):
    """The blockMeshDict of the shell between the cubes of half side 1 and
    2 (straight edges: every radial block edge and grid line lies on a ray
    from the origin), graded along the rays, and the level's parameters;
    map_points() then puts it onto the spheres (outer radius R1 + margin,
    the shell's Shell.margin)."""
    lev = LEVELS[level]
    n, n_r, ds_w = lev.n, lev.n_r, lev.ds_w
    R2 = R1 + margin
    # radial grading from the wall: the block's third direction runs from
    # the outer to the inner cube, so its ratio last/first is the inverse
    # of the growth outwards
    ratio = 1.0/expansion(margin, n_r, ds_w)

    def corners(r):
        return [(sx*r, sy*r, sz*r) for (sx, sy, sz) in
                [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                 (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]]

    verts = corners(1.0) + corners(2.0)     # 0-7 inner, 8-15 outer
    # the six shell blocks of blockMesh's sphere7 tutorial topology, inner
    # cube vertices 0-7, outer 8-15
    blocks = [(9, 8, 12, 13, 1, 0, 4, 5), (10, 9, 13, 14, 2, 1, 5, 6),
              (11, 10, 14, 15, 3, 2, 6, 7), (8, 11, 15, 12, 0, 3, 7, 4),
              (8, 9, 10, 11, 0, 1, 2, 3), (13, 12, 15, 14, 5, 4, 7, 6)]
    inner_faces = [(0, 4, 7, 3), (2, 6, 5, 1), (1, 5, 4, 0), (3, 7, 6, 2),
                  (0, 3, 2, 1), (4, 5, 6, 7)]
    outer_faces = [tuple(v + 8 for v in f) for f in inner_faces]

    out = ["FoamFile { version 2.0; format ascii; class dictionary; "
           "object blockMeshDict; }",
           "// Sphere body component, level %s: n %d, nR %d, "
           "dsW %g m (R1 %g m, R2 %g m); the cube shell |x|_max in [1, 2] "
           "is mapped onto the spherical shell by sphereMesh.py -map"
           % (level, n, n_r, ds_w, R1, R2),
           "scale 1;",
           "vertices", "("]
    out += ["    (%g %g %g)  // %d" % (v + (i,)) for i, v in enumerate(verts)]
    out += [");", "blocks", "("]
    for b in blocks:
        out.append("    hex (%s) body (%d %d %d) simpleGrading (1 1 %.12g)"
                   % (" ".join(str(v) for v in b), n, n, n_r, ratio))
    out += [");", "edges ();", "boundary", "("]
    out += ["    body", "    {", "        type wall;", "        faces",
            "        ("]
    out += ["            (%s)" % " ".join(map(str, f)) for f in inner_faces]
    out += ["        );", "    }"]
    out += ["    oversetPatch", "    {", "        type overset;",
            "        faces", "        ("]
    out += ["            (%s)" % " ".join(map(str, f)) for f in outer_faces]
    out += ["        );", "    }", ");"]
    return "\n".join(out) + "\n", dict(level=level, n=n, nR=n_r, dsW=ds_w,
                                       growth=1.0/ratio, R1=R1, R2=R2,
                                       cells=6*n*n*n_r)


# The cubed sphere is turned by a fixed rotation (TURN_AXIS, TURN_ANGLE) so
# that its panel seams (the planes x = +-y, y = +-z, z = +-x of the cube)
# are not planes of symmetry of the background: unturned, background cell
# centres lay exactly on the seams (the background is symmetric about the
# body centre and moves with it), i.e. on a face shared by two body cells,
# an exact tie that the stock and the octree donor searches break
# differently (4 of 2514 acceptors at the first step, the body force then
# 2.4 % apart).  A sphere is a sphere: the turn only moves the seams.  A
# case may give another (Shell): the two-wing drone's turns about y only,
# so that the mesh stays its own mirror image about y = 0.
TURN_AXIS = (1.0, 2.0, 3.0)
TURN_ANGLE = 0.3            # [rad]


@dataclass(frozen=True)
class Shell:
    """The shell as mapped: its outer margin (R2 = R1 + margin) and the
    turn of its panels (axis, angle [rad])."""
    margin: float = MARGIN
    axis: tuple = TURN_AXIS
    angle: float = TURN_ANGLE


SHELL = Shell()             # the body-wing drone's


def turn(v, axis=TURN_AXIS, angle=TURN_ANGLE):
    """v rotated by angle about axis (Rodrigues)."""
    k = tuple(a/math.sqrt(sum(b*b for b in axis)) for a in axis)
    c, s = math.cos(angle), math.sin(angle)
    kv = sum(a*b for a, b in zip(k, v))
    kxv = (k[1]*v[2] - k[2]*v[1], k[2]*v[0] - k[0]*v[2],
           k[0]*v[1] - k[1]*v[0])
    return tuple(v[i]*c + kxv[i]*s + k[i]*kv*(1 - c) for i in range(3))


def map_points(path, centre=(0.0, 0.0, 0.0), shell=SHELL):
    """Map the points of the cube shell (an ascii polyMesh points file) onto
    the spherical shell: a point p with rho = max |p_i| in [1, 2] goes to
    the radius R1 + (rho - 1)(R2 - R1) along its ray (R2 = R1 +
    shell.margin), turned by shell.angle about shell.axis (see TURN_AXIS),
    then to centre.  Returns the number of points."""
    R2 = R1 + shell.margin

    def mapped(p):
        x, y, z = p
        rho = max(abs(x), abs(y), abs(z))
        r = R1 + (rho - 1.0)*(R2 - R1)
        norm = math.sqrt(x*x + y*y + z*z)
        d = turn((x/norm, y/norm, z/norm), shell.axis, shell.angle)
        return (centre[0] + r*d[0], centre[1] + r*d[1], centre[2] + r*d[2])
    return rewrite_points(path, mapped)


def refine_actions(margin, centre=(0.0, 0.0, 0.0), shell=SHELL):
    """The topoSet actions that add the body component's ball (radius R1 +
    shell.margin), grown by a refinement pass's margin, to a refinement
    region."""
    return [("add", "sphereToCell",
             "origin (%.9g %.9g %.9g);\n        radius %.9g;"
             % (tuple(centre) + (R1 + shell.margin + margin,)))]


class TextDict:
    """A dictionary given as text, written like a BlockMesh
    (block_mesh.write_case)."""

    def __init__(self, text):
        self.text = text

    def write(self, path, header=""):
        with open(path, "w") as fh:
            fh.write(header + self.text)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    ap.add_argument("level", nargs="?")
    ap.add_argument("-o", default=None)
    ap.add_argument("-centre", nargs=3, type=float, default=[0.0, 0.0, 0.0])
    ap.add_argument("-map", metavar="POINTS",
                    help="map the cube-shell points file (ascii) onto the "
                         "spheres instead")
    ap.add_argument("-list", action="store_true")
    a = ap.parse_args(argv)
    if a.map:
        n = map_points(a.map, tuple(a.centre))
        print("sphereMesh: mapped %d points of %s" % (n, a.map),
              file=sys.stderr)
        return 0
    if a.list or not a.level:
        for k, v in LEVELS.items():
            print("%-9s n %d nR %d dsW %g cells %d"
                  % (k, v.n, v.n_r, v.ds_w, 6*v.n**2*v.n_r))
        return 0
    if a.level not in LEVELS:
        sys.exit("sphereMesh.py: level %s: one of %s"
                 % (a.level, ", ".join(LEVELS)))
    text, info = block_mesh_dict(a.level)
    if a.o:
        os.makedirs(os.path.dirname(os.path.abspath(a.o)), exist_ok=True)
        with open(a.o, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    print("sphereMesh: %s" % info, file=sys.stderr)
    return 0
