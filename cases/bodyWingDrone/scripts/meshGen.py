#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Body-wing drone overset mesh generator (flapFoam, cases/bodyWingDrone).

Writes, for one resolution level, the dictionaries of the three component
meshes that scripts/makeMesh turns into the overset mesh:

  <out>/wing/system/blockMeshDict         wing component (cellZone "wing"):
                                          the single-wing drone's
                                          (../singleWingDrone/scripts/
                                          meshGen.py), same level parameters
  <out>/body/system/blockMeshDict         body component (cellZone "body"):
                                          the cube shell of sphereMesh.py,
                                          mapped onto the spheres after
                                          blockMesh (sphereMesh.py --map)
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
  meshGen.py <level> [-o DIR] [--phi DEG] [--alpha DEG]
  meshGen.py --list

The wing's axes pass through the body centre (the origin), so the wing
component is the single-wing drone's at the same pose.  Units: metres.
"""

import argparse
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "singleWingDrone",
                                "scripts"))
import meshGen as sw  # noqa: E402  (the single-wing drone's generator)
import sphereMesh  # noqa: E402

# Body pitch the refined region allows for (the stroke plane tilts with it)
THETA_MAX = math.radians(20)

# The wing component of the single-wing drone (its margin at each level),
# its root side 7 mm from the root: 0.5 mm off the body (radius 15 mm, root
# at 22.5 mm), never inside it, so that the body's walls need not cut it
# (system/fvSchemes: noHoleCut ((2 1))).  Checked over a whole cycle with
# Allrun -motionOnly.  The layouts that failed there, all with the stock
# hole cutting of every pair of zones:
#  - root side 12 mm from the root (inside the sphere): the sphere's voxels
#    cut the wing cells near the root, the fringe walk from those holes ran
#    through the wing cells next to the plate, which have no donor (the
#    background and body cells there are holes);
#  - 6 mm (and 4.5 or 5 mm with 0.55 mm voxels): the sphere's voxels still
#    cut the big outer wing cells of the root side at some poses; the body
#    cells next to the plate's holes then found no donor (t = 0.00125 s);
#  - 6 mm without the sphere cutting the wing (noHoleCut): the voxels of
#    the plate's root faces (their boxes, when pitched, reach 2 mm inboard)
#    cut the body cells where the wing's root side takes its donors, at
#    t = 0.0185 s; 7 mm and 2 mm body cells there (sphereMesh.py) pass
COMPONENT = dict(sw.COMPONENT, rootMargin=7e-3)


class textDict:
    """A dictionary given as text, written like a BlockMesh"""

    def __init__(self, text):
        self.text = text

    def write(self, path, header=""):
        with open(path, "w") as fh:
            fh.write(header + self.text)


def refineActions(region, margin):
    """The body component's ball, grown by the pass's margin, added to a
    refinement region"""
    c = (0.0, 0.0, 0.0)
    return [("add", "sphereToCell",
             "origin (%.9g %.9g %.9g);\n        radius %.9g;"
             % (c + (sphereMesh.R1 + sphereMesh.MARGIN + margin,)))]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("level", nargs="?", choices=list(sphereMesh.LEVELS))
    ap.add_argument("-o", "--output", default="mesh")
    ap.add_argument("--phi", type=float, default=0.0,
                    help="initial flapping angle of the wing [deg]")
    ap.add_argument("--alpha", type=float, default=0.0,
                    help="initial pitching angle of the wing [deg]")
    ap.add_argument("--list", action="store_true",
                    help="print the planned cell counts of every level")
    args = ap.parse_args(argv)

    tilts = (-THETA_MAX, 0.0, THETA_MAX)
    if args.list:
        for name in sphereMesh.LEVELS:
            lev = sw.LEVELS[name]
            comp = sw.levelComponent(COMPONENT, lev)
            _, winfo = sw.wingComponent(lev, comp)
            _, binfo = sw.backgroundMesh(
                lev, sw.BACKGROUND,
                sw.sweptEnvelope(comp, sw.BACKGROUND, tilts))
            _, sinfo = sphereMesh.blockMeshDict(name)
            print("%-9s wing %7d cells, body %6d cells, background h %.2f mm"
                  % (name, winfo["cellsPlanned"], sinfo["cells"],
                     1e3*binfo["h"]))
        return 0
    if args.level is None:
        ap.error("level required")

    lev = sw.LEVELS[args.level]
    comp = sw.levelComponent(COMPONENT, lev)
    env = sw.sweptEnvelope(comp, sw.BACKGROUND, tilts)
    pose = (math.radians(args.phi), math.radians(args.alpha))
    wbm, winfo = sw.wingComponent(lev, comp, pose)
    sw.checkBlockSides(wbm)
    bbm, binfo = sw.backgroundMesh(lev, sw.BACKGROUND, env)
    stext, sinfo = sphereMesh.blockMeshDict(args.level)

    hdr = ("// Generated by scripts/meshGen.py %s: do not edit\n"
           % " ".join(sys.argv[1:] if argv is None else argv))
    sw.writeCase(os.path.join(args.output, "wing"), wbm,
                 hdr + "// Body-wing drone: wing component (O-type, overset)"
                 "\n\n")
    sw.writeCase(os.path.join(args.output, "body"),
                 textDict(stext.split("\n", 1)[1]),
                 sw.FOAM_HEADER % ("dictionary", "blockMeshDict") + hdr)
    extra = {"topoSetDict.refine%d" % (j + 1):
             sw.topoSetRefine(r, sw.BACKGROUND["centre"],
                              refineActions(r, binfo["margins"][j]))
             for j, r in enumerate(binfo["regions"])}
    sw.writeCase(os.path.join(args.output, "background"), bbm,
                 hdr + "// Body-wing drone: background cube\n\n", extra)

    summary = dict(components=[dict(name="wing"),
                               dict(name="body",
                                    post=["sphereMesh.py", "--map"]),
                               dict(name="background")],
                   level=args.level, levelParameters=lev,
                   pose=dict(phiDeg=args.phi, alphaDeg=args.alpha),
                   thetaMaxDeg=math.degrees(THETA_MAX),
                   wing=winfo, body=sinfo, background=binfo)
    with open(os.path.join(args.output, "meshGen.json"), "w") as fh:
        json.dump(summary, fh, indent=2, default=float)
    print("meshGen: level %s: wing %d cells, body %d cells, background "
          "%d^3 cells refined %d times (h = %.3g m)"
          % (args.level, winfo["cellsPlanned"], sinfo["cells"], lev["N0"],
             lev["nRef"], binfo["h"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
