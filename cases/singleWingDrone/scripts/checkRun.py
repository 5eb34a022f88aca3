#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Checks of drone runs (PASS/FAIL lines): flapfoam.check_run (usage there)."""

import sys

from flapfoam.check_run import main

if __name__ == "__main__":
    sys.exit(main())
