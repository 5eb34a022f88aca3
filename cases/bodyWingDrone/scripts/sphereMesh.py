#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Body-wing drone: the body's component mesh, flapfoam.mesh.sphere_mesh
(usage there; the panels turned about (1 2 3) by 0.3 rad, its default)."""

import sys

from flapfoam.mesh.sphere_mesh import main

if __name__ == "__main__":
    sys.exit(main())
