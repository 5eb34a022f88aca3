#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Two-wing drone overset mesh generator (flapFoam, cases/twoWingDrone).

Writes, for one resolution level, the dictionaries of the four component
meshes that scripts/makeMesh turns into the overset mesh (merged in this
order: the left wing's overset patch is the master):

  <out>/leftWing/system/blockMeshDict    the body-wing drone's wing
                                         component (flapfoam.mesh.wing_mesh,
                                         its root side 10 mm from the root);
                                         after blockMesh moved to the hinge
                                         y = +HINGE, zone and patch
                                         leftWing (placeMesh.py leftWing)
  <out>/rightWing/system/blockMeshDict   the same; after blockMesh the
                                         mirror image of the left wing's
                                         (placeMesh.py rightWing:
                                         flapfoam.mesh.poly_mesh.mirror)
  <out>/body/system/blockMeshDict        the body-wing drone's sphere
                                         (flapfoam.mesh.sphere_mesh), its
                                         panels turned about y only so that
                                         it stays its own mirror image
                                         (placeMesh.py body)
  <out>/background/system/blockMeshDict  background cube of 20 chords
  <out>/background/system/topoSetDict.refine<i>  refinement regions: the
                                         cylinder about z that holds what
                                         both wing components sweep
                                         (|phi| <= 75 deg, |alpha| <= 45
                                         deg, stroke plane pitched by up to
                                         +-thetaMax with the body, hinges at
                                         y = +-HINGE) and the body
                                         component, plus margins
  <out>/meshGen.json                     parameters and planned sizes

Usage:
  meshGen.py <level> [-o DIR] [-phi DEG] [-alpha DEG]
  meshGen.py -list | -levels

-phi, -alpha pose the left wing's component (the right one mirrored);
Allrun's eABA motion starts from the mesh at q = 0.  Units: metres.
"""

import dataclasses
import math
import os
import sys

from flapfoam.mesh import mesh_gen
from flapfoam.mesh import sphere_mesh
from flapfoam.mesh import wing_mesh
from flapfoam.mesh.block_mesh import FOAM_HEADER, write_case
from flapfoam.mesh.parameters import file_entries

# The wings' hinges (flapping and pitching axes) at y = +-HINGE, on the
# sphere: with both through the body centre the wings would cross at the
# stroke's ends; at +-15 mm the plates stay 23 mm apart (21 mm in the roll
# variant), more than a wing component's margin (18 mm on tiny), so that
# neither comes into the other's component (a plate through a component
# cuts it in two, and the hole cutting takes one part for a hole: at +-7.5
# mm, 3 532 of 7 884 cells of each wing at t = 1 ms).  README.md,
# "Geometry"; constant/dynamicMeshDict.eABA's leftFlap and rightFlap
# transforms give the same number
HINGE = 15e-3
# Body pitch the refined region allows for (the stroke plane tilts with it)
THETA_MAX = math.radians(20)
# The body-wing drone's wing component, its root side 10 mm from the root
# (at 7 mm the holes ran through both wing components at t = 5 ms), 0.1 mm
# off the sphere at 80 deg of flapping (the roll variant's), so that the
# body's walls need not cut it (system/fvSchemes noHoleCut)
COMPONENT = dataclasses.replace(wing_mesh.COMPONENT, root_margin=10e-3)
# The body component: the body-wing drone's sphere, its shell 25 mm deep (to
# 40 mm from the centre, over the wing roots, 37.5 mm out, as the body-wing
# drone's shell is over its wing's root: with its 12 mm the holes ran
# through both wing components at t = 8.5 ms), its panels turned about y
# only so that it stays its own mirror image (placeMesh.py body)
SHELL = sphere_mesh.Shell(margin=25e-3, axis=(0.0, 1.0, 0.0))
WINGS = ("leftWing", "rightWing")
# The wing components' margins where they differ from the level's (tiny:
# 1.2 cbar, not 1.0: with 15 mm the flight's poses at 6-7 deg of body
# pitch left a wing's overset-boundary cell in a background hole, and the
# hole flooded both wings; README.md, "Overset assembly")
MARGINS = {"tiny": 18e-3}


def both_sides(region):
    """A refinement region of the wing about its hinge turned into one about
    the body centre that holds both wings' sweeps: the cylinder rA grown by
    the hinge's offset, whole (the one-wing region's half-space y >= yA
    reaches past y = 0 by more than HINGE on every level)."""
    if region["yA"] + HINGE > 0:
        raise ValueError("region %s: the two sides leave a gap at y = 0"
                         % region)
    return dict(region, rA=region["rA"] + HINGE, yA=None, rB=0.0)


def main(argv=None):
    args = mesh_gen.parse_args(__doc__, sphere_mesh.LEVELS, argv)
    tilts = (-THETA_MAX, 0.0, THETA_MAX)
    if args.list:
        for name in sphere_mesh.LEVELS:
            m = mesh_gen.build(name, COMPONENT, tilts=tilts,
                               margin=MARGINS.get(name))
            _, sinfo = sphere_mesh.block_mesh_dict(name, SHELL.margin)
            print("%-9s wings 2 x %7d cells, body %6d cells, background h "
                  "%.2f mm" % (name, m.winfo["cellsPlanned"], sinfo["cells"],
                               1e3*m.binfo["h"]))
        return 0

    m = mesh_gen.build(args.level, COMPONENT,
                       mesh_gen.pose(args.phi, args.alpha), tilts,
                       MARGINS.get(args.level))
    m.binfo["regions"] = [both_sides(r) for r in m.binfo["regions"]]
    stext, sinfo = sphere_mesh.block_mesh_dict(args.level, SHELL.margin)
    hdr = mesh_gen.header(argv)
    mesh_gen.write_wing_and_background(
        args.output, hdr, "Two-wing drone", m,
        lambda j, r: sphere_mesh.refine_actions(m.binfo["margins"][j],
                                                shell=SHELL),
        wings=WINGS)
    write_case(os.path.join(args.output, "body"),
               sphere_mesh.TextDict(stext.split("\n", 1)[1]),
               FOAM_HEADER % ("dictionary", "blockMeshDict") + hdr)

    summary = dict(components=[dict(name=w, post=["placeMesh.py", w])
                               for w in WINGS] +
                   [dict(name="body", post=["placeMesh.py", "body"]),
                    dict(name="background")],
                   level=args.level,
                   levelParameters=file_entries(m.lev),
                   pose=dict(phiDeg=args.phi, alphaDeg=args.alpha),
                   hinge=HINGE, thetaMaxDeg=math.degrees(THETA_MAX),
                   wing=m.winfo, body=sinfo, background=m.binfo)
    return mesh_gen.finish(
        args.output, summary,
        "meshGen: level %s: wings 2 x %d cells, body %d cells, background "
        "%d^3 cells refined %d times (h = %.3g m)"
        % (args.level, m.winfo["cellsPlanned"], sinfo["cells"], m.lev.n0,
           m.lev.n_ref, m.binfo["h"]))


if __name__ == "__main__":
    sys.exit(main())
