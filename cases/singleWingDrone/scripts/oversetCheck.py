#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Orphan check of the overset stencil of a run: flapfoam.meshChecks."""

import os
import sys

sys.path.insert(0, os.environ.get("FLAPFOAM_PROJECT_DIR", os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "../../..")) + "/scripts")
from flapfoam.meshChecks import oversetCheck  # noqa: E402

if __name__ == "__main__":
    sys.exit(oversetCheck())
