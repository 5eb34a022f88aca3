# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Edits of a component's polyMesh as blockMesh writes it (ascii), before the
components are merged (bin/tools/makeOversetMesh runs a component's "post"
command on it): every point mapped (rewrite_points: the sphere's shell of
sphere_mesh, a wing moved to its hinge), the mirror image about the plane
y = 0 (mirror: y -> -y of every point, every face's vertices reversed so
that its normal points from the owner to the neighbour again; owner,
neighbour and the cell, face and point order unchanged, so that cell i of
the mirror is the mirror image of cell i), and a cell zone and a patch
renamed (rename).  No numpy.
"""

import os
import re

_COUNT = re.compile(r"\n(\d+)\s*\(\s*\n")
_TRIPLE = re.compile(r"\(([^()]*)\)\s*")
_FACE = re.compile(r"(\d+)\(([^()]*)\)")


def _list_start(text, path):
    """The match of '<count> (' after the FoamFile header."""
    m = _COUNT.search(text, text.index("}", text.index("FoamFile")))
    if not m:
        raise ValueError("%s: no list after the header" % path)
    return m


def rewrite_points(path, fn, fmt="(%.15g %.15g %.15g)"):
    """Each point p of an ascii points file replaced by fn(p) (a tuple of
    three floats), written with fmt; returns the number of points."""
    text = open(path).read()
    m = _list_start(text, path)
    count = int(m.group(1))
    pos = m.end()
    pts = []
    for _ in range(count):
        t = _TRIPLE.match(text, pos)
        pts.append(fn(tuple(float(v) for v in t.group(1).split())))
        pos = t.end()
    rest = text[pos:]
    if not rest.startswith(")"):
        raise ValueError("%s: no ')' after %d points" % (path, count))
    with open(path, "w") as f:
        f.write(text[:m.start()] + "\n%d\n(\n" % count)
        f.write("\n".join(fmt % p for p in pts))
        f.write("\n" + rest)
    return count


def reverse_faces(path):
    """Every face of an ascii faces file (faceList) reversed, its first
    vertex kept (a b c d -> a d c b); returns the number of faces."""
    text = open(path).read()
    m = _list_start(text, path)
    end = text.rindex(")")
    count = 0

    def flipped(f):
        nonlocal count
        count += 1
        v = f.group(2).split()
        return "%s(%s)" % (f.group(1), " ".join(v[:1] + v[:0:-1]))
    body = _FACE.sub(flipped, text[m.end():end])
    if count != int(m.group(1)):
        raise ValueError("%s: %d faces read, %s listed"
                         % (path, count, m.group(1)))
    with open(path, "w") as f:
        f.write(text[:m.end()] + body + text[end:])
    return count


def mirror(poly_mesh):
    """The polyMesh folder turned into its mirror image about y = 0."""
    rewrite_points(os.path.join(poly_mesh, "points"),
                   lambda p: (p[0], -p[1], p[2]))
    return reverse_faces(os.path.join(poly_mesh, "faces"))


def rename(poly_mesh, old, new):
    """The cell zone and the patch named old renamed new (cellZones,
    boundary); ValueError if either has no such entry."""
    for name in ("cellZones", "boundary"):
        path = os.path.join(poly_mesh, name)
        text = open(path).read()
        out, n = re.subn(r"(\n\s*)%s(\s*\n\s*\{)" % re.escape(old),
                         r"\g<1>%s\g<2>" % new, text)
        if n != 1:
            raise ValueError("%s: %d entries named %s" % (path, n, old))
        with open(path, "w") as f:
            f.write(out)
