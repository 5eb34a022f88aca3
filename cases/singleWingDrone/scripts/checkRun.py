#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Checks of drone runs (PASS/FAIL lines): flapfoam.checks.check_run (usage there)."""

import sys

from flapfoam.checks.check_run import main

if __name__ == "__main__":
    sys.exit(main())
