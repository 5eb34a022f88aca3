#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Body-wing drone overset mesh generator (flapFoam, cases/bodyWingDrone).

Writes, for one resolution level, the dictionaries of the three component
meshes that scripts/makeMesh turns into the overset mesh:

  <out>/wing/system/blockMeshDict         wing component (cellZone "wing"):
                                          the single-wing drone's
                                          (flapfoam.mesh.wing_mesh), same level
                                          parameters
  <out>/body/system/blockMeshDict         body component (cellZone "body"):
                                          the cube shell of sphereMesh.py,
                                          mapped onto the spheres after
                                          blockMesh (sphereMesh.py -map)
  <out>/background/system/blockMeshDict   background cube (cellZone
                                          "background") of 20 chords
  <out>/background/system/topoSetDict.refine<i>  refinement regions: the
                                          volume the wing component sweeps
                                          (|phi| <= 75 deg, |alpha| <= 45
                                          deg, stroke plane pitched by up to
                                          +-thetaMax with the body) and the
                                          body component, plus margins
  <out>/meshGen.json                      parameters and planned sizes

Usage:
  meshGen.py <level> [-o DIR] [-phi DEG] [-alpha DEG]
  meshGen.py -list

The wing's axes pass through the body centre (the origin), so the wing
component is the single-wing drone's at the same pose.  Units: metres.
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

# Body pitch the refined region allows for (the stroke plane tilts with it)
THETA_MAX = math.radians(20)

# The wing component of the single-wing drone (its margin at each level),
# its root side 7 mm from the root, outside the body (radius 15 mm, root at
# 22.5 mm), so that the body's walls need not cut it (system/fvSchemes:
# noHoleCut ((2 1))).  Why this layout, and the layouts that failed a whole
# cycle of Allrun -motionOnly: README.md, "Whole cycles".
COMPONENT = dataclasses.replace(wing_mesh.COMPONENT, root_margin=7e-3)


def main(argv=None):
    args = mesh_gen.parse_args(__doc__, sphere_mesh.LEVELS, argv)
    tilts = (-THETA_MAX, 0.0, THETA_MAX)
    if args.list:
        for name in sphere_mesh.LEVELS:
            m = mesh_gen.build(name, COMPONENT, tilts=tilts)
            _, sinfo = sphere_mesh.block_mesh_dict(name)
            print("%-9s wing %7d cells, body %6d cells, background h %.2f mm"
                  % (name, m.winfo["cellsPlanned"], sinfo["cells"],
                     1e3*m.binfo["h"]))
        return 0

    m = mesh_gen.build(args.level, COMPONENT,
                       mesh_gen.pose(args.phi, args.alpha), tilts)
    stext, sinfo = sphere_mesh.block_mesh_dict(args.level)
    hdr = mesh_gen.header(argv)
    mesh_gen.write_wing_and_background(
        args.output, hdr, "Body-wing drone", m,
        lambda j, r: sphere_mesh.refine_actions(m.binfo["margins"][j]))
    write_case(os.path.join(args.output, "body"),
              sphere_mesh.TextDict(stext.split("\n", 1)[1]),
              FOAM_HEADER % ("dictionary", "blockMeshDict") + hdr)

    summary = dict(components=[dict(name="wing"),
                               dict(name="body",
                                    post=["sphereMesh.py", "-map"]),
                               dict(name="background")],
                   level=args.level,
                   levelParameters=file_entries(m.lev),
                   pose=dict(phiDeg=args.phi, alphaDeg=args.alpha),
                   thetaMaxDeg=math.degrees(THETA_MAX),
                   wing=m.winfo, body=sinfo, background=m.binfo)
    return mesh_gen.finish(
        args.output, summary,
        "meshGen: level %s: wing %d cells, body %d cells, background "
        "%d^3 cells refined %d times (h = %.3g m)"
        % (args.level, m.winfo["cellsPlanned"], sinfo["cells"], m.lev.n0,
           m.lev.n_ref, m.binfo["h"]))


if __name__ == "__main__":
    sys.exit(main())
