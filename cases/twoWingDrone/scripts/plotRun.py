#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Plots of a two-wing drone run: flapfoam.plots.drone (usage there) with
this drone's hook (-drone twoWing): the x-z path of the body's centre
(trajectory.png), the flight data's force coefficients of both wings and
the body (forceCoefficients.png), the body's attitude, yaw, pitch and roll
(attitude.png), the four prescribed joints against their Wang motion
(prescribedJoints.png) and the step timers (stepTimers.png).
"""

import sys

import numpy as np

from flapfoam.errors import FlapFoamError, run_tool
from flapfoam.plots import drone
from flapfoam.plots.plotting import plt, save

BODIES = ("leftWing", "rightWing", "body")


def coefficients(run):
    """Both wings' and the body's C_xI, C_zI: the flight data's."""
    out = {}
    for body in BODIES:
        b = run.series.bodies.get(body)
        if b is None or b.coefficients is None:
            raise FlapFoamError("plotRun: no coefficients/%s in the flight "
                                "data of %s" % (body, run.name))
        out[body] = (b.coefficients[1:, 0], b.coefficients[1:, 1])
    return out


def attitude(run, out):
    """The body's yaw, pitch and roll (q_3, q_4, q_5) and its y."""
    q = run.series.q
    fig, axes = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for qi, name in ((3, "yaw psi = q_3"), (4, "pitch theta = q_4"),
                     (5, "roll = q_5")):
        axes[0].plot(run.f*run.t, np.degrees(q[:, qi]), label=name)
    axes[0].set_ylabel("[deg]")
    axes[0].legend(fontsize=8)
    axes[0].set_title("Attitude of the body (%s)" % run.model.split(":")[0])
    axes[1].plot(run.f*run.t, 1e3*q[:, 1])
    axes[1].set_ylabel("y = q_1 [mm]")
    axes[1].set_xlabel("t f [cycles]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    save(fig, out, "attitude.png")
    print("plotRun: final yaw %.6g, pitch %.6g, roll %.6g deg, y %.6g m"
          % (tuple(np.degrees(q[-1, 3:6])) + (q[-1, 1],)))


drone.DRONES["twoWing"] = drone.Drone(
    "Two-wing drone", drone.body_centre,
    ("x [mm]", "z [mm]", "path of the body's centre of mass"),
    coefficients, {"attitude": attitude})

if __name__ == "__main__":
    sys.exit(run_tool(drone.main, None, "twoWing"))
