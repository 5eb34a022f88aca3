# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.mesh.poly_mesh on a one-cell polyMesh written as blockMesh
writes it (ascii): the mirror image about y = 0 (points exactly, face
normals the mirror images of the originals), a zone and a patch renamed."""

import numpy as np
import pytest

from flapfoam.io import foam_mesh
from flapfoam.mesh import poly_mesh

HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    object      %s;
}
"""
# a hexahedron 0.1 x 0.2 x 0.3 off the origin, its faces pointing outwards
POINTS = [(0.0, 0.05, 0.0), (0.1, 0.05, 0.0), (0.1, 0.25, 0.0),
          (0.0, 0.25, 0.0), (0.0, 0.05, 0.3), (0.1, 0.05, 0.3),
          (0.1, 0.25, 0.3), (0.0, 0.25, 0.3)]
FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (3, 7, 6, 2),
         (0, 4, 7, 3), (1, 2, 6, 5)]


def write_mesh(folder):
    with open(folder / "points", "w") as f:
        f.write(HEADER % ("vectorField", "points") + "\n\n%d\n(\n" % 8
                + "\n".join("(%.12g %.12g %.12g)" % p for p in POINTS)
                + "\n)\n")
    with open(folder / "faces", "w") as f:
        f.write(HEADER % ("faceList", "faces") + "\n\n6\n(\n"
                + "\n".join("4(%d %d %d %d)" % q for q in FACES) + "\n)\n")
    with open(folder / "cellZones", "w") as f:
        f.write(HEADER % ("regIOobject", "cellZones") + "\n1\n(\nwing\n{\n"
                "    type cellZone;\ncellLabels      List<label> 1(0);\n}\n)\n")
    with open(folder / "boundary", "w") as f:
        f.write(HEADER % ("polyBoundaryMesh", "boundary") + "\n2\n(\n"
                "    oversetPatch\n    {\n        type overset;\n"
                "        nFaces 5;\n        startFace 0;\n    }\n"
                "    wing\n    {\n        type wall;\n        nFaces 1;\n"
                "        startFace 5;\n    }\n)\n")


def area_vectors(folder):
    points = foam_mesh.read_points(str(folder / "points"))
    offs, verts = foam_mesh.read_faces(str(folder / "faces"))
    return points, foam_mesh.face_areas_vec(points, offs, verts,
                                            np.arange(len(offs) - 1))


def test_mirror_is_the_exact_mirror_image_with_outward_faces(tmp_path):
    write_mesh(tmp_path)
    points, areas = area_vectors(tmp_path)
    assert poly_mesh.mirror(str(tmp_path)) == 6
    mirrored, mirrored_areas = area_vectors(tmp_path)
    m = np.array([1.0, -1.0, 1.0])
    # points: y negated, to the last bit
    assert np.array_equal(mirrored, points*m)
    # face area vectors: the mirror images of the originals (outwards
    # again), to 1e-15 of their size
    assert np.abs(mirrored_areas - areas*m).max() <= 1e-15
    # the first vertex kept, the others reversed
    offs, verts = foam_mesh.read_faces(str(tmp_path / "faces"))
    assert list(verts[offs[0]:offs[1]]) == [0, 1, 2, 3]


def test_rename_renames_the_zone_and_the_patch_only(tmp_path):
    write_mesh(tmp_path)
    poly_mesh.rename(str(tmp_path), "wing", "rightWing")
    assert foam_mesh.read_zone_sizes(str(tmp_path / "cellZones")) == \
        {"rightWing": 1}
    assert sorted(foam_mesh.read_boundary(str(tmp_path / "boundary"))) == \
        ["oversetPatch", "rightWing"]
    with pytest.raises(ValueError):
        poly_mesh.rename(str(tmp_path), "wing", "leftWing")
