#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Checks of the wing's overset mesh after makeMesh: flapfoam.meshChecks."""

import sys

from flapfoam.meshChecks import meshCheck

if __name__ == "__main__":
    sys.exit(meshCheck())
