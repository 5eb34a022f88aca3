#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Orphan check of the overset stencil of a run: flapfoam.checks.mesh_checks."""

import sys

from flapfoam.checks.mesh_checks import overset_check

if __name__ == "__main__":
    sys.exit(overset_check())
