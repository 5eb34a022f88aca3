# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
An independent reference of the quasi-steady blade-element wing (the
definition of bodyLoads::aerodynamics / quasiSteady, written apart from the
C++) and of the single-wing drone's translational equations under it.

The single-wing tree (Pz heave, Px surge, Rz flapping, Ry pitching, the
wing's centre of mass on both rotation axes) moves its mass only through
the two translations, so with the wing's rotations prescribed
    m x'' = F_x,   m z'' = F_z - m g
is exact; the force is the blade elements' at the wing's current motion.

    flapfoam quasi_steady DYNAMICMESHDICT -cycles 5 -out FILE
        [-compare JOINTS.DAT -tol 1e-3]

writes t x z xDot zDot (one row per output step) from rest at t = 0; with
-compare, the x(t), z(t) of a rigidBodySimulate run's joints.dat (columns
time q_0 qDot_0 qDdot_0 q_1 ...: q_0 heave z, q_1 surge x) at its rows,
and a non-zero exit if either differs by more than tol times the
reference's range over the run.
numpy and scipy.
"""

import argparse
import math
import sys

import numpy as np
from scipy.integrate import solve_ivp

from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.models.wang import imposed_joints
from flapfoam.errors import run_tool


def vec(tokens):
    return np.array([float(v) for v in tokens if v not in ("(", ")")])


class Wing:
    """The strips of one quasiSteady entry (the issue's definition): each
    strip's force acts at its chordwise centre of pressure, d = (CoP0 +
    CoP1 2 alpha/pi) c from the pitch axis along the chord direction
    (0, 0 by default: on the axis)."""

    def __init__(self, entry):
        R = float(entry["length"][0])
        self.length = R
        N = int(entry.get("nStrips", ["40"])[0])
        r = (np.arange(N) + 0.5)*R/N
        if entry["chordDistribution"][0] == "semiElliptic":
            cbar = float(entry["meanChord"][0])
            c = 4.0*cbar/math.pi*np.sqrt(1.0 - (r/R)**2)
        else:
            table = vec(entry["chords"]).reshape(-1, 2)
            c = np.interp(r, table[:, 0], table[:, 1])
        self.chords = c
        self.area = c*R/N
        self.span = vec(entry["span"])
        self.chord = vec(entry["chord"])
        self.root = vec(entry["root"])
        self.points = self.root + np.outer(r, self.span)
        self.rho = float(entry["rho"][0])
        self.CL = float(entry.get("CL", ["1.2"])[0])
        self.CD0 = float(entry.get("CD0", ["0.4"])[0])
        self.CD1 = float(entry.get("CD1", ["1.0"])[0])
        self.CoP0 = float(entry.get("CoP0", ["0"])[0])
        self.CoP1 = float(entry.get("CoP1", ["0"])[0])
        self.wind = vec(entry.get("wind", ["0", "0", "0"]))

    def strips(self, E, v_origin, omega):
        """The loaded strips for the body's orientation E (body -> global),
        its origin's velocity and angular velocity: a dict of their index
        (live), arm (global, from the origin), angle of attack alpha,
        force d_f, and the global span and chord directions s, c."""
        s, c = E @ self.span, E @ self.chord
        n = np.cross(c, s)
        arm = self.points @ E.T
        u = self.wind - (v_origin + np.cross(omega, arm))
        u_perp = u - np.outer(u @ s, s)
        U = np.linalg.norm(u_perp, axis=1)
        live = U >= 1e-12
        e_d = u_perp[live]/U[live, None]
        alpha = np.arccos(np.minimum(1.0, np.abs(e_d @ c)))
        e_l = np.cross(s, e_d)
        e_l /= np.linalg.norm(e_l, axis=1)[:, None]
        e_l *= np.where((e_l @ n)*(u_perp[live] @ n) < 0, -1.0, 1.0)[:, None]
        CL = self.CL*np.sin(2*alpha)
        CD = self.CD0 + self.CD1*(1 - np.cos(2*alpha))
        d_f = (0.5*self.rho*U[live]**2*self.area[live])[:, None] \
            *(CL[:, None]*e_l + CD[:, None]*e_d)
        return {"live": live, "arm": arm[live], "alpha": alpha, "d_f": d_f,
                "s": s, "c": c}

    def centre_of_pressure(self, strips):
        """Each live strip's offset from its pitch-axis point along the
        chord [m]."""
        return (self.CoP0 + self.CoP1*2*strips["alpha"]/math.pi) \
            * self.chords[strips["live"]]

    def force(self, E, origin, v_origin, omega):
        """Force and moment (global origin) for the body's orientation E
        (body -> global), origin position and velocity, angular velocity."""
        st = self.strips(E, v_origin, omega)
        at = origin + st["arm"] \
            + np.outer(self.centre_of_pressure(st), st["c"])
        return st["d_f"].sum(axis=0), np.cross(at, st["d_f"]).sum(axis=0)


def rotation(axis, angle):
    c, s = math.cos(angle), math.sin(angle)
    if axis == "z":
        return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


class SingleWingDrone:
    """x, z of the single-wing tree (joints 0 Pz, 1 Px, 2 Rz, 3 Ry)."""

    def __init__(self, coeffs):
        wing = coeffs["bodies"]["wing"]
        self.mass = float(wing["mass"][0])
        self.g = -vec(coeffs.get("g", ["0", "0", "0"]))[2]
        joints = imposed_joints(coeffs)
        self.phi, self.alpha = joints[2], joints[3]
        entries = [e for e in coeffs["aerodynamics"].values()
                   if isinstance(e, dict)]
        self.wing = Wing(entries[0])

    def wing_motion(self, t):
        """The wing's orientation E (body -> global) and angular velocity
        at t (the prescribed flapping and pitching)."""
        phi, phi_dot, _ = self.phi(t)
        alpha, alpha_dot, _ = self.alpha(t)
        Rz = rotation("z", float(phi))
        E = Rz @ rotation("y", float(alpha))
        omega = np.array([0, 0, float(phi_dot)]) \
            + float(alpha_dot)*(Rz @ np.array([0, 1, 0]))
        return E, omega

    def rhs(self, t, y):
        x, z, x_dot, z_dot = y
        E, omega = self.wing_motion(t)
        F, _ = self.wing.force(E, np.array([x, 0, z]),
                               np.array([x_dot, 0, z_dot]), omega)
        return [x_dot, z_dot, F[0]/self.mass, F[2]/self.mass - self.g]

    def fly(self, end_time, dt):
        t = np.arange(0, end_time + 0.5*dt, dt)
        sol = solve_ivp(self.rhs, (0, t[-1]), [0, 0, 0, 0], t_eval=t,
                        method="DOP853", rtol=1e-10, atol=1e-13)
        return np.column_stack([sol.t, sol.y.T])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("dict", help="dynamicMeshDict with an aerodynamics"
                        " entry in its multibody coefficients")
    parser.add_argument("-cycles", type=float, default=5)
    parser.add_argument("-dt", type=float, default=1e-4,
                        help="output interval [s]")
    parser.add_argument("-out", required=True)
    parser.add_argument("-compare", metavar="JOINTS.DAT")
    parser.add_argument("-tol", type=float, default=1e-3)
    args = parser.parse_args()
    if args.cycles <= 0 or args.dt <= 0:
        parser.error("-cycles %g, -dt %g: both must be positive"
                     % (args.cycles, args.dt))
    drone = SingleWingDrone(multibody_coeffs(args.dict))
    end_time = args.cycles/drone.phi.frequency
    ref = drone.fly(end_time, args.dt)
    np.savetxt(args.out, ref, header="t x z xDot zDot")
    if args.compare:
        err = errors(ref, np.loadtxt(args.compare))
        for name, e in err.items():
            print("quasi_steady: %s: max |run - reference| = %.3g of its"
                  " range (tol %g)" % (name, e, args.tol))
        sys.exit(0 if max(err.values()) <= args.tol else 1)


def errors(ref, run):
    """{"z": e, "x": e}: the largest |run - reference| of a joints.dat's
    (rows of run) z and x, each relative to the reference's range."""
    out = {}
    for name, col, ref_col in (("z", 1, 2), ("x", 4, 1)):
        value = np.interp(run[:, 0], ref[:, 0], ref[:, ref_col])
        scale = ref[:, ref_col].max() - ref[:, ref_col].min()
        out[name] = float(np.abs(run[:, col] - value).max()/scale)
    return out


if __name__ == "__main__":
    run_tool(main)
