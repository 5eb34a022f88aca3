# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Synthetic flight data of the single-wing drone for the qsCalibrate test:
the tree flown from rest by the independent quasi-steady reference
(flapfoam.models.quasi_steady.SingleWingDrone) with the chosen CL, CD0, CD1, and
its wing's rows as the flightData function object writes them (centre of
mass position and velocity, from the dictionary's centreOfMass, row-major
orientation, angular velocity, force; the first row's loads NaN).

    flapfoam synthetic_flight_data CASE -CL A -CD0 B -CD1 C
        [-cycles N] [-dt DT] [-thinAfter T] [-noForce]

reads CASE/constant/dynamicMeshDict and writes
CASE/postProcessing/flightData/0/flightData.h5 (-thinAfter: every other
row after time T left out, steps of 2 DT as a run with a varying step;
-noForce: without bodies/wing/force).  numpy, scipy and h5py.
"""

import argparse
import os

import h5py
import numpy as np

from flapfoam.errors import run_tool
from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.models.quasi_steady import SingleWingDrone, vec


def wing_rows(drone, states, centre):
    """{dataset: rows} of the wing along the flown states (t x z xDot
    zDot)."""
    d = {k: [] for k in ("orientation", "position", "velocity",
                         "angularVelocity", "force")}
    for t, x, z, x_dot, z_dot in states:
        E, omega = drone.wing_motion(t)
        origin, v_origin = np.array([x, 0, z]), np.array([x_dot, 0, z_dot])
        F, _ = drone.wing.force(E, origin, v_origin, omega)
        d["orientation"].append(E.reshape(9))
        d["position"].append(origin + E @ centre)
        d["velocity"].append(v_origin + np.cross(omega, E @ centre))
        d["angularVelocity"].append(omega)
        d["force"].append(F)
    d = {k: np.array(v) for k, v in d.items()}
    d["force"][0] = np.nan
    return d


def main(argv=None):
    parser = argparse.ArgumentParser(prog="flapfoam synthetic_flight_data",
                                     description=__doc__.split("\n\n")[0])
    parser.add_argument("case")
    for k in ("CL", "CD0", "CD1"):
        parser.add_argument("-" + k, type=float, required=True)
    parser.add_argument("-cycles", type=float, default=1)
    parser.add_argument("-dt", type=float, default=1e-4)
    parser.add_argument("-thinAfter", dest="thin_after", type=float,
                        default=float("inf"))
    parser.add_argument("-noForce", dest="no_force", action="store_true")
    args = parser.parse_args(argv)
    coeffs = multibody_coeffs(os.path.join(args.case, "constant",
                                          "dynamicMeshDict"))
    drone = SingleWingDrone(coeffs)
    drone.wing.CL, drone.wing.CD0, drone.wing.CD1 = args.CL, args.CD0, \
        args.CD1
    states = drone.fly(args.cycles/drone.phi.frequency, args.dt)
    late = states[:, 0] > args.thin_after
    states = states[~late | (np.cumsum(late) % 2 == 0)]
    centre = vec(coeffs["bodies"]["wing"]["centreOfMass"])
    d = wing_rows(drone, states, centre)
    folder = os.path.join(args.case, "postProcessing", "flightData", "0")
    os.makedirs(folder, exist_ok=True)
    with h5py.File(os.path.join(folder, "flightData.h5"), "w") as f:
        f["time"] = states[:, 0]
        for k, v in d.items():
            if not (args.no_force and k == "force"):
                f["bodies/wing/" + k] = v


if __name__ == "__main__":
    run_tool(main)
