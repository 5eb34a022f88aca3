#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Checks of the wing's overset mesh after makeMesh: flapfoam.checks.mesh_checks."""

import sys

from flapfoam.checks.mesh_checks import mesh_check

if __name__ == "__main__":
    sys.exit(mesh_check())
