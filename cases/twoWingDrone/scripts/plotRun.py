#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Plots of a two-wing drone run: flapfoam.plots.drone (usage there) with
-drone twoWing: the x-z path of the body's centre (trajectory.png), the
flight data's force coefficients of both wings and the body
(forceCoefficients.png), the body's attitude, yaw, pitch and roll
(attitude.png), the four prescribed joints against their Wang motion
(prescribedJoints.png) and the step timers (stepTimers.png).
"""

import sys

from flapfoam.errors import run_tool
from flapfoam.plots.drone import main

if __name__ == "__main__":
    sys.exit(run_tool(main, None, "twoWing"))
