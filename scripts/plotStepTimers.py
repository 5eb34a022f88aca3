#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Bar chart of the step timers of runs: flapfoam.plot_step_timers (usage
there)."""


from flapfoam.plot_step_timers import main

if __name__ == "__main__":
    main()
