#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Checks of drone runs (PASS/FAIL lines): flapfoam.checkRun (usage there)."""

import os
import sys

sys.path.insert(0, os.environ.get("FLAPFOAM_PROJECT_DIR", os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "../../..")) + "/scripts")
from flapfoam.checkRun import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
