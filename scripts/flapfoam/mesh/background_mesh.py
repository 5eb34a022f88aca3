# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The background cube of the drone meshes: uniform hex cells refined in
nested regions (topoSetDict.refine<i>, refineHexMesh) that contain the
volume the components sweep (wingMesh.sweptEnvelope).  numpy only.
"""

import math
from dataclasses import dataclass

import numpy as np

from flapfoam.models import wing_geometry as geo
from flapfoam.mesh.block_mesh import BlockMesh, FOAM_FOOTER, FOAM_HEADER

# --------------------------------------------------------------------------
# Background and motion envelope
@dataclass(frozen=True)
class Background:
    """The background cube and the motion envelope it is refined around."""
    side: float             # cube side [m]
    centre: tuple
    phi_max: float          # A_phi
    alpha_max: float        # A_alpha
    n_buffer: int           # cells of each level between refinement
                            # regions (a level may set its own)
    final_margin: int       # cells of size h beyond the swept component


BACKGROUND = Background(side=20*geo.CBAR, centre=(0.0, 0.0, 0.0),
                        phi_max=math.radians(75), alpha_max=math.radians(45),
                        n_buffer=2, final_margin=1)


def background_cell_size(lev, bg):
    return bg.side/(lev.n0*2**lev.n_ref)


def background_block_mesh(lev, bg, env):
    side = bg.side
    c = np.asarray(bg.centre, dtype=float)
    N0, n_ref = lev.n0, lev.n_ref
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
            bm.set_sizes(verts[a_], verts[b_], np.full(N0, h0))
    b = bm.block(verts, "background")
    bm.patch("farField", "patch")
    for side_ in BlockMesh.HEX_FACES:
        bm.face("farField", b, side_)

    # nested refinement regions, finest last
    h = [h0/2**j for j in range(n_ref + 1)]     # h[j]: size after pass j
    margins = [0.0]*(n_ref + 1)
    # a cell is selected when its centre is in the region: half a cell of
    # the pass's input size added to each margin
    m = bg.final_margin*h[n_ref] + 0.5*h[n_ref - 1]
    margins[n_ref] = m
    for j in range(n_ref - 1, 0, -1):
        m = m + (bg.n_buffer if lev.n_buffer is None else lev.n_buffer)*h[j] \
            + 0.5*h[j - 1]
        margins[j] = m
    regions = []
    for j in range(1, n_ref + 1):
        m = margins[j]
        regions.append(dict(
            rA=env["rMax"] + m, z=env["zMax"] + m, yA=env["yA"] - m,
            rB=env["rB"] + m if env["rB"] > 0 else 0.0))
    info = dict(h0=h0, h=h[n_ref], nRef=n_ref, N0=N0, margins=margins[1:],
                regions=regions, envelope=env)
    return bm, info


def topo_set_refine(region, centre, extra=()):
    """topoSetDict of a refinement pass: the region's cylinders (the
    cylinder rA without the half-space y < yA, unless yA is None, and the
    cylinder rB), and the extra actions (action, source, body) after
    them."""
    c = centre
    big = 10.0
    acts = [
        ("new", "cylinderToCell",
         "p1 (%.9g %.9g %.9g);\n        p2 (%.9g %.9g %.9g);\n"
         "        radius %.9g;" % (c[0], c[1], c[2] - region["z"],
                                   c[0], c[1], c[2] + region["z"],
                                   region["rA"])),
    ]
    if region["yA"] is not None:        # None: the whole cylinder
        acts.append(
            ("subtract", "boxToCell",
             "box (%.9g %.9g %.9g) (%.9g %.9g %.9g);"
             % (-big, -big, -big, big, region["yA"], big)))
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


