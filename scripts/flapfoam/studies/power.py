# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The power a drone's flight takes: the prescribed joints' mean mechanical
power over whole flapping cycles, per kilogram, and the figure of merit of
the flapping wings as hovering rotors (docs/trim.md, "Power").

    flapfoam power RUN [RUN ...] [-from C] [-to C] [-flapping ENTRY]
        [-radius R] [-json FILE] [-summary FILE -label L] [-plot FILE]

RUN: a drone run folder (CFD or Allrun -model quasiSteady): its flight data
and its constant/dynamicMeshDict (the bodies' masses and inertias, g, the
imposedMotion entry -flapping, default flapping: its joint and frequency;
the aerodynamics entries: the wings' tip radius and the air's density).
Over the whole cycles from cycle -from (default 0) to -to (default: the
last whole one), time-integrated (trapezoids: the CFD's step is adaptive):

    P_joint    the mean of sum_j tau_j qDot_j over the prescribed joints:
               the power the actuators give, negative parts included (a
               perfect elastic store); P_joint+ with each joint's negative
               power lost (no store)
    P_aero     P_joint - dE/dt, E the bodies' kinetic and potential energy
               (the mean of dE/dt is the change over the window over its
               length): the power the wings give the air
    P_ideal    sqrt(T^3/(2 rho A)), momentum theory's induced power of a
               rotor of disk area A carrying T = the weight m |g|: A the
               wings' swept sectors, sum over the wings of Phi R^2/2 (Phi:
               the flapping joint's peak-to-peak angle over the window, R:
               a wing's tip radius |root + length span|, or -radius)
    FM         P_ideal/P_aero, the figure of merit

in W and W/kg (m: every body's mass, the tree's whole mass).  -json FILE:
every number; -summary FILE -label L (one RUN): the keys power_w_per_kg_L,
figure_of_merit_L and power_L (every number) merged into a results
folder's summary.json; -plot FILE: a PNG of each run's cycle-mean joint
power per kg (its mean and its ideal power beside it).  numpy, h5py,
matplotlib.
"""

import argparse
import json
import math
import os
import sys
from dataclasses import dataclass

import numpy as np

from flapfoam.errors import run_tool
from flapfoam.io import run_series
from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.studies.qs_case import StudyError, write_summary


@dataclass
class Window:
    """The cycles of a run to average over: the first, the last (None: the
    last whole one), and the cycle's length T [s]."""
    first: int
    last: int
    period: float

    def bounds(self, t):
        """(t0, t1, n): the window's times and its number of cycles."""
        whole = int(math.floor((t[-1] - t[0])/self.period + 1e-9))
        last = whole if self.last is None else self.last
        if not 0 <= self.first < last <= whole:
            raise StudyError("cycles %d to %s: not allowed (the run holds"
                             " %d whole cycles: 0 <= -from < -to <= %d)"
                             % (self.first, last, whole, whole))
        return t[0] + self.first*self.period, t[0] + last*self.period, \
            last - self.first


def numbers(entry, key, count):
    """The count numbers of a dictionary entry's vector or scalar key."""
    words = [w for w in entry.get(key, []) if w not in "()"]
    if len(words) != count:
        raise StudyError("%s: %s numbers expected, found %s" % (
            key, count, " ".join(entry.get(key, [])) or "none"))
    return np.array([float(w) for w in words])


class Drone:
    """The masses, inertias and gravity of a run's multibody dictionary,
    its flapping entry and its wings' aerodynamics entries."""

    def __init__(self, run, flapping):
        path = os.path.join(run, "constant", "dynamicMeshDict")
        self.coeffs = multibody_coeffs(path)
        self.path = path
        self.bodies = {n: b for n, b in self.coeffs.get("bodies", {}).items()
                       if isinstance(b, dict) and "mass" in b}
        self.g = numbers(self.coeffs, "g", 3)
        motions = self.coeffs.get("imposedMotion", {})
        if flapping not in motions:
            raise StudyError("%s: no imposedMotion entry %s (allowed: %s)"
                             % (path, flapping, " ".join(sorted(motions))))
        self.joint = int(motions[flapping]["joint"][0])
        self.period = 1/float(motions[flapping]["frequency"][0])

    @property
    def mass(self):
        return sum(float(b["mass"][0]) for b in self.bodies.values())

    def wings(self, radius):
        """[(R, rho)] of the aerodynamics entries (R: -radius if given)."""
        out = []
        for name, e in self.coeffs.get("aerodynamics", {}).items():
            if isinstance(e, dict):
                tip = numbers(e, "root", 3) + float(e["length"][0]) \
                    * numbers(e, "span", 3)
                out.append((radius or float(np.linalg.norm(tip)),
                            float(e["rho"][0])))
        if not out:
            raise StudyError("%s: no aerodynamics entry (the wings' tip"
                             " radius and the air's density)" % self.path)
        return out

    def energy(self, series, rows):
        """The bodies' kinetic and potential energy at the rows [J]."""
        e = 0.0
        for name, b in self.bodies.items():
            s = series.bodies[name]
            m = float(b["mass"][0])
            inertia = numbers(b, "inertia", 6)
            J = np.array([[inertia[0], inertia[1], inertia[2]],
                          [inertia[1], inertia[3], inertia[4]],
                          [inertia[2], inertia[4], inertia[5]]])
            R = s.orientation[rows].reshape(-1, 3, 3)
            w = np.einsum("kji,kj->ki", R, s.angular_velocity[rows])
            e = e + 0.5*m*np.sum(s.velocity[rows]**2, axis=1) \
                + 0.5*np.einsum("ki,ij,kj->k", w, J, w) \
                - m*s.position[rows] @ self.g
        return e


def mean_over(t, y, t0, t1):
    """The time mean of y over [t0, t1] (trapezoids, y interpolated at the
    ends)."""
    inside = (t > t0) & (t < t1)
    tt = np.concatenate(([t0], t[inside], [t1]))
    yy = np.concatenate(([np.interp(t0, t, y)], y[inside],
                         [np.interp(t1, t, y)]))
    return float(np.trapz(yy, tt)/(t1 - t0))


def power(run, window, flapping="flapping", radius=None):
    """The numbers of the module docstring for one run."""
    drone = Drone(run, flapping)
    window = Window(window.first, window.last, window.period or drone.period)
    s = run_series.read(run)
    t0, t1, n = window.bounds(s.time)
    ok = np.all(np.isfinite(s.power), axis=1)   # the first row: no load
    t, p = s.time[ok], s.power[ok]
    mass, weight = drone.mass, drone.mass*float(np.linalg.norm(drone.g))
    joints = [mean_over(t, p[:, k], t0, t1) for k in range(p.shape[1])]
    positive = sum(mean_over(t, np.maximum(p[:, k], 0), t0, t1)
                   for k in range(p.shape[1]))
    ends = [int(np.argmin(abs(s.time - x))) for x in (t0, t1)]
    change = np.diff(drone.energy(s, ends))[0]/(s.time[ends[1]]
                                                - s.time[ends[0]])
    inside = (s.time >= t0) & (s.time <= t1)
    phi = np.ptp(s.q[inside, drone.joint])
    wings = drone.wings(radius)
    area = sum(phi*R**2/2 for R, _ in wings)
    rho = wings[0][1]
    ideal = math.sqrt(weight**3/(2*rho*area))
    aero = sum(joints) - change
    total = p.sum(axis=1)
    per_cycle = [mean_over(t, total, t0 + k*window.period,
                           t0 + (k + 1)*window.period)/mass
                 for k in range(n)]
    return {"run": run, "cycles": [window.first, window.first + n],
            "period_s": window.period, "mass_kg": mass,
            "joint_power_w": dict(zip(("q_%d" % i for i in s.prescribed),
                                      joints)),
            "power_w": sum(joints), "power_w_per_kg": sum(joints)/mass,
            "cycle_power_w_per_kg": per_cycle,
            "power_positive_w_per_kg": positive/mass,
            "energy_change_w": float(change), "aero_power_w": aero,
            "stroke_amplitude_rad": float(phi), "disk_area_m2": area,
            "ideal_power_w": ideal, "figure_of_merit": ideal/aero}


def plot(results, path):
    """One PNG: each run's cycle-mean joint power per kg over its window
    (its mean dashed), and its ideal power per kg (dotted)."""
    from flapfoam.plots.plotting import plt, save
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for r in results:
        first = r["cycles"][0]
        cycles = np.arange(first, first + len(r["cycle_power_w_per_kg"])) + 1
        name = os.path.basename(os.path.normpath(r["run"]))
        line, = ax.plot(cycles, r["cycle_power_w_per_kg"], "o-",
                        label="%s: %.1f W/kg, FM %.3f"
                        % (name, r["power_w_per_kg"], r["figure_of_merit"]))
        ax.axhline(r["power_w_per_kg"], color=line.get_color(), ls="--",
                   lw=0.8)
        ax.axhline(r["ideal_power_w"]/r["mass_kg"], color=line.get_color(),
                   ls=":", lw=0.8)
    ax.set_xlabel("cycle")
    ax.set_ylabel("joint power [W/kg]")
    ax.set_title("cycle-mean joint power (dashed: the mean; dotted: ideal)",
                 fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, os.path.dirname(path) or ".", os.path.basename(path))
    print("power: wrote %s" % path)


def arguments(argv):
    parser = argparse.ArgumentParser(
        prog="flapfoam power", description=__doc__.split("\n\n")[1].strip(),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", metavar="RUN")
    parser.add_argument("-from", dest="first", type=int, default=0)
    parser.add_argument("-to", dest="last", type=int)
    parser.add_argument("-period", type=float)
    parser.add_argument("-flapping", default="flapping")
    parser.add_argument("-radius", type=float)
    parser.add_argument("-json", metavar="FILE")
    parser.add_argument("-summary", metavar="FILE")
    parser.add_argument("-label")
    parser.add_argument("-plot", metavar="FILE")
    args = parser.parse_args(argv)
    if args.summary and not (args.label and len(args.runs) == 1):
        parser.error("-summary: needs -label L and one RUN")
    for option, v in (("-period", args.period), ("-radius", args.radius)):
        if v is not None and not (v > 0 and math.isfinite(v)):
            parser.error("%s %g: not allowed (> 0)" % (option, v))
    if args.first < 0:
        parser.error("-from %d: not allowed (a cycle >= 0)" % args.first)
    return args


def main(argv=None):
    args = arguments(argv)
    window = Window(args.first, args.last, args.period)
    try:
        results = [power(r, window, args.flapping, args.radius)
                   for r in args.runs]
    except (StudyError, OSError, KeyError) as e:
        sys.exit("power: %s" % e)
    for r in results:
        print("power: %s, cycles %d-%d: %.4g W/kg (joints, elastic store;"
              " %.4g without), aero %.4g W, ideal %.4g W, FM %.3f"
              % (r["run"], r["cycles"][0], r["cycles"][1],
                 r["power_w_per_kg"], r["power_positive_w_per_kg"],
                 r["aero_power_w"], r["ideal_power_w"],
                 r["figure_of_merit"]))
    if args.plot:
        plot(results, args.plot)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    if args.summary:
        r = results[0]
        write_summary(args.summary, {
            "power_w_per_kg_" + args.label: r["power_w_per_kg"],
            "figure_of_merit_" + args.label: r["figure_of_merit"],
            "power_" + args.label: r})


if __name__ == "__main__":
    run_tool(main)
