# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
blockMeshDict writing for the drone meshes: the BlockMesh writer with its
edge-wise grading bookkeeping, 1-D cell distributions reproduced exactly by
multi-section grading, the FoamFile header and the minimal system/ of a
component's case.  numpy only.
"""

import os

import numpy as np


# --------------------------------------------------------------------------
# 1-D cell distributions
# --------------------------------------------------------------------------

def sizes_geometric(L, N, d0, d1=None, q=1.2):
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


def n_cells_growth(L, d0, d_end, q):
    """Cells to cover L starting at d0, growing by q up to dEnd, then
    uniform dEnd."""
    n, s, x = 0, d0, 0.0
    while x < L*(1 - 1e-9):
        x += min(s, d_end)
        s *= q
        n += 1
    return n


def grading_sections(sizes, tol=1e-6):
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


def fmt_grading(sizes):
    secs = grading_sections(sizes)
    if len(secs) == 1:
        return "%.10g" % secs[0][2]
    return "(" + " ".join("(%.12g %.12g %.12g)" % s for s in secs) + ")"


# --------------------------------------------------------------------------
# The writer
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

    def set_sizes(self, a, b, s):
        s = np.asarray(s, dtype=float)
        if (b, a) in self.sizes:
            raise KeyError("edge %s given twice" % ((a, b),))
        self.sizes[(a, b)] = s

    def get_sizes(self, a, b):
        if (a, b) in self.sizes:
            return self.sizes[(a, b)]
        return self.sizes[(b, a)][::-1]

    def curved(self, a, b, pts3):
        if (b, a) in self.edges or (a, b) in self.edges:
            return
        self.edges[(a, b)] = np.asarray(pts3, dtype=float)

    def block(self, verts, zone):
        n = [len(self.get_sizes(verts[0], verts[1])),
             len(self.get_sizes(verts[0], verts[3])),
             len(self.get_sizes(verts[0], verts[4]))]
        for k, (i, j) in enumerate(self.HEX_EDGES):
            nn = len(self.get_sizes(verts[i], verts[j]))
            if nn != n[k//4]:
                raise ValueError("inconsistent cell count on block %s edge "
                                 "%d: %d vs %d" % (verts, k, nn, n[k//4]))
        self.blocks.append((list(verts), zone, n))
        return len(self.blocks) - 1

    def face(self, patch, block_i, side):
        verts = self.blocks[block_i][0]
        self.patches[patch][1].append(
            tuple(verts[i] for i in self.HEX_FACES[side]))

    def patch(self, name, ptype):
        self.patches[name] = (ptype, [])

    def n_cells(self):
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
            gr = [fmt_grading(self.get_sizes(verts[i], verts[j]))
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


def write_case(path, bm, header, extra=None):
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


