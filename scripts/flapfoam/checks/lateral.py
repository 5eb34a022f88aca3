# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Two-wing drone: the lateral states of a run (its flight data,
postProcessing/flightData/*/flightData.h5): the largest |y|, |yaw|, |roll|
(q_1, q_3, q_5) and their rates over the run, the position and attitude at
its end, and the mean roll and yaw rates of each whole flapping cycle (the
difference of the angle over the cycle, deg per cycle).

    flapfoam lateral [-case DIR] [-f HZ] [-zero] [-rollRate SIGN] [-quiet]

-zero: "PASS" if every lateral state and rate is exactly 0 in every row,
else "FAIL"; -rollRate +1 (-1): "PASS" if the last whole cycle's mean roll
rate is positive (negative) and at least 0.1 deg per cycle; -quiet: only
those lines.  Exit status 1 if a check fails.  numpy, h5py.
"""

import argparse
import math
import sys

import numpy as np

from flapfoam.errors import run_tool
from flapfoam.io import flight_data

LATERAL = {"y": 1, "yaw": 3, "roll": 5}


def cycle_rates(t, angle, f):
    """[(k, mean rate [deg/cycle])] of each whole cycle k of the run."""
    n = int(math.floor((t[-1] - t[0])*f + 1e-9))
    ends = t[0] + np.arange(n + 1)/f
    a = np.degrees(np.interp(ends, t, angle))
    return [(k + 1, a[k + 1] - a[k]) for k in range(n)]


def main(argv=None):
    ap = argparse.ArgumentParser(prog="flapfoam lateral",
                                 description=__doc__.split("\n\n")[1])
    ap.add_argument("-case", default=".")
    ap.add_argument("-f", type=float, default=20.0,
                    help="flapping frequency [Hz] (default 20)")
    ap.add_argument("-zero", action="store_true")
    ap.add_argument("-rollRate", type=int, choices=[-1, 1])
    ap.add_argument("-quiet", action="store_true",
                    help="only the PASS/FAIL lines of -zero, -rollRate")
    a = ap.parse_args(argv)
    say = (lambda *args: None) if a.quiet else print
    _, data = flight_data.load(a.case)
    t = np.asarray(data["time"], dtype=float)
    q = np.asarray(data["joints/q"], dtype=float)
    qd = np.asarray(data["joints/qDot"], dtype=float)
    cols = list(LATERAL.values())
    worst = float(np.abs(q[:, cols]).max())
    worst_rate = float(np.abs(qd[:, cols]).max())
    for name, i in LATERAL.items():
        scale = 1.0 if name == "y" else 180/math.pi
        unit = "m" if name == "y" else "deg"
        say("lateral: max |%s| %.6g %s, max |rate| %.6g %s/s"
              % (name, scale*np.abs(q[:, i]).max(), unit,
                 scale*np.abs(qd[:, i]).max(), unit))
    say("lateral: at t = %.6g s: x y z %.6g %.6g %.6g m, yaw pitch roll "
          "%.6g %.6g %.6g deg" % ((t[-1],) + tuple(q[-1, :3])
                                  + tuple(np.degrees(q[-1, 3:6]))))
    rates = {n: cycle_rates(t, q[:, LATERAL[n]], a.f) for n in ("roll", "yaw")}
    for (k, roll), (_, yaw) in zip(rates["roll"], rates["yaw"]):
        say("lateral: cycle %d: mean roll rate %.6g deg/cycle, yaw rate "
              "%.6g deg/cycle" % (k, roll, yaw))
    status = 0
    if a.zero:
        ok = worst == 0.0 and worst_rate == 0.0
        print("%s lateral states y, yaw, roll and their rates exactly 0 in "
              "all %d rows (max |q| %g, |qDot| %g)"
              % ("PASS" if ok else "FAIL", len(t), worst, worst_rate))
        status |= not ok
    if a.rollRate:
        last = rates["roll"][-1][1] if rates["roll"] else 0.0
        ok = a.rollRate*last >= 0.1
        print("%s roll rate of the last whole cycle %.6g deg/cycle (expected "
              "%s, at least 0.1 in size)"
              % ("PASS" if ok else "FAIL", last,
                 "positive" if a.rollRate > 0 else "negative"))
        status |= not ok
    return status


if __name__ == "__main__":
    sys.exit(run_tool(main))
