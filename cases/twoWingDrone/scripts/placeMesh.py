#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Two-wing drone: a component mesh put in place after blockMesh (the "post"
command of meshGen.json, run by bin/tools/makeOversetMesh on the
component's constant/polyMesh/points):

    placeMesh.py leftWing POINTS    the wing moved to its hinge (y +
                                    HINGE), zone and patch wing renamed
                                    leftWing
    placeMesh.py rightWing POINTS   the same, then its mirror image about
                                    y = 0 (flapfoam.mesh.poly_mesh.mirror:
                                    y -> -y, faces reversed), renamed
                                    rightWing: exactly the left wing's
                                    mirror image, point for point
    placeMesh.py body POINTS        the cube shell mapped onto the spheres
                                    (flapfoam.mesh.sphere_mesh), the
                                    meshGen.py's SHELL: the panels turned
                                    about y, which keeps the shell its own
                                    mirror image
"""

import argparse
import os
import sys

from meshGen import HINGE, SHELL
from flapfoam.mesh import poly_mesh
from flapfoam.mesh import sphere_mesh


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[1])
    ap.add_argument("component",
                    choices=["leftWing", "rightWing", "body"])
    ap.add_argument("points", help="the component's polyMesh points file")
    a = ap.parse_args(argv)
    if a.component == "body":
        n = sphere_mesh.map_points(a.points, shell=SHELL)
        print("placeMesh: body: %d points on the spheres" % n)
        return 0
    mesh = os.path.dirname(a.points)
    n = poly_mesh.rewrite_points(a.points,
                                 lambda p: (p[0], p[1] + HINGE, p[2]))
    if a.component == "rightWing":
        poly_mesh.mirror(mesh)
    poly_mesh.rename(mesh, "wing", a.component)
    print("placeMesh: %s: %d points%s" % (a.component, n, ", mirrored"
                                           if a.component == "rightWing"
                                           else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
