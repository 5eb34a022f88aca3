#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
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
  meshGen.py <level> [-o DIR] [-phi DEG] [-alpha DEG]
  meshGen.py -list

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

The levels, the component's topology and the background are those of
flapfoam.mesh.wing_mesh and flapfoam.mesh.background_mesh (shared with the body-wing
drone).  Units: metres.  Python: /usr/bin/python3 (numpy).
"""

import sys

from flapfoam.mesh import mesh_gen
from flapfoam.models import wing_geometry as geo
from flapfoam.mesh.background_mesh import BACKGROUND
from flapfoam.mesh.parameters import file_entries
from flapfoam.mesh.wing_mesh import COMPONENT, LEVELS


def main(argv=None):
    args = mesh_gen.parse_args(__doc__, LEVELS, argv)
    if args.list:
        for name in LEVELS:
            m = mesh_gen.build(name, COMPONENT)
            print("%-9s wing blocks %7d cells (nR %d nZ %d)  background "
                  "h %.2f mm" % (name, m.winfo["cellsPlanned"],
                                 m.winfo["nR"], m.winfo["nZ"],
                                 1e3*m.binfo["h"]))
        return 0

    m = mesh_gen.build(args.level, COMPONENT,
                       mesh_gen.pose(args.phi, args.alpha))
    mesh_gen.write_wing_and_background(args.output, mesh_gen.header(argv),
                                   "Single-wing drone", m)
    # components in merge order (bin/tools/makeOversetMesh): the wing is the
    # master, so that its overset patch becomes the first patch
    summary = dict(components=[dict(name="wing"), dict(name="background")],
                   level=args.level,
                   levelParameters=file_entries(m.lev),
                   pose=dict(phiDeg=args.phi, alphaDeg=args.alpha),
                   geometry=geo.summary(),
                   component=file_entries(m.comp),
                   wing=m.winfo, background=m.binfo,
                   backgroundParameters=file_entries(BACKGROUND))
    return mesh_gen.finish(
        args.output, summary,
        "meshGen: level %s: wing %d cells in %d blocks, background "
        "%d^3 cells refined %d times (h = %.3g m)"
        % (args.level, m.winfo["cellsPlanned"], m.winfo["blocks"],
           m.lev.n0, m.lev.n_ref, m.binfo["h"]))


if __name__ == "__main__":
    sys.exit(main())
