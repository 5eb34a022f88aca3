#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Plots of a body-wing drone run: flapfoam.plots.drone -drone bodyWing (usage there)."""

import sys

from flapfoam.plots.drone import main
from flapfoam.errors import run_tool

if __name__ == "__main__":
    sys.exit(run_tool(main, None, "bodyWing"))
