#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Bar chart of the step timers of runs: flapfoam.plotStepTimers (usage
there)."""

import sys

from flapfoam.plotStepTimers import main

if __name__ == "__main__":
    main()
