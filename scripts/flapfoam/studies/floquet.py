# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Floquet analysis of a periodic flight on the quasi-steady (QS) model: the
monodromy matrix (the Jacobian of the one-cycle map at the trimmed state)
by central differences, its eigenvalues (the Floquet multipliers) and,
per mode, the period, the time to double or halve and the states it moves
most; optionally a kick along the most unstable mode, flown.

    flapfoam floquet [-case cases/bodyWingDrone] [-variant hover ...]
        [-edits FILE] [-deltaT DT] [-step 1e-5] [-kick 1e-4]
        [-kickCycles 4] [-np 1] [-o PREFIX] [-summary FILE] [-dir DIR]
        [-keep]

The flight: the case with its variants (e.g. one written by flapfoam trim
-write) and -edits (e.g. a trim's PREFIX.variant), its kinematics and its
initial state (the dictionary's q, qDot) at
the start of a cycle, x*; the state (flapfoam.studies.cycle_map): the free
rotations' angles and every free joint's velocity (the positions of free
translations are left out: the map does not depend on them, each would add
a multiplier of exactly 1).  Column j of the monodromy matrix M:

    (Phi(x* + h_j e_j) - Phi(x* - h_j e_j)) / (2 h_j),  h_j = step*scale_j

(Phi: one cycle of rigidBodySimulate; scale_j: 1 rad, 1 rad per cycle, g T;
-step 1e-5 by default: the differences' truncation error is of order
step^2, their round-off of order 1e-15/step).  The fixed point's own
mismatch |Phi(x*) - x*| (scaled) is printed: above 1e-6 the flight is not
periodic (trim it first).  Per mode (eigenvalue mu of M, eigenvector v):
|mu| (> 1: grows), ln|mu| per cycle, a complex pair's period 2 pi/|arg mu|
cycles (a negative real mu: 2 cycles), the cycles to double (|mu| > 1)
or to halve (|mu| < 1), ln 2/|ln|mu||, and the states v moves most (v in
the scaled states, the largest component 1; those of 0.05 or more, with
their phase).  -kick EPS: from x* + EPS Re(v) (scaled) of the mode of the
largest |mu|, flown -kickCycles cycles beside x*'s own flight; the mode's
coordinate (the rows of V^-1 on the difference) per cycle over the one
before, against mu.  -o PREFIX: PREFIX.json (the modes, the monodromy
matrix, the fixed point), PREFIX.png (the multipliers, the modes, the
kick); -summary FILE: the Floquet keys merged into FILE (a results
folder's summary.json).  numpy, matplotlib.
"""

import argparse
import json
import math
import os
import sys
from dataclasses import dataclass

import numpy as np

from flapfoam.errors import run_tool
from flapfoam.paths import project_path
from flapfoam.studies.cycle_map import CycleMap, MapSettings, read_edits
from flapfoam.studies.qs_case import (StudyError, check_ranges,
                                       write_summary)

# the Floquet keys of the results' summary.json (PREFIX.json has them all)
SUMMARY_KEYS = ("floquet_multipliers", "floquet_states",
                "floquet_step_scaled", "floquet_period_s", "floquet_fixed_point_mismatch",
                "floquet_modes", "unstable_mode_period_cycles",
                "unstable_mode_doubling_cycles", "floquet_kick_ratio_error")


def monodromy(phi, x, steps):
    """Central differences of the map phi (a list of states -> the list
    of their images) at x, with the steps h_j of each state."""
    n = len(x)
    points = []
    for j in range(n):
        for sign in (1.0, -1.0):
            xj = np.array(x, dtype=float)
            xj[j] += sign*steps[j]
            points.append(xj)
    images = np.array(phi(points))
    return np.column_stack([(images[2*j] - images[2*j + 1])/(2*steps[j])
                            for j in range(n)])


@dataclass
class Mode:
    """One Floquet mode: the multiplier mu, its eigenvector (in the scaled
    states, the largest component 1) and what follows from them."""
    multiplier: complex
    vector: np.ndarray

    @property
    def modulus(self):
        return abs(self.multiplier)

    @property
    def growth_per_cycle(self):
        """ln|mu|: the exponent per cycle."""
        return math.log(self.modulus)

    @property
    def period_cycles(self):
        """2 pi/|arg mu| of a complex mu, 2 of a negative real one, None
        of a positive real one."""
        angle = abs(np.angle(self.multiplier))
        return 2*math.pi/angle if angle > 1e-12 else None

    @property
    def doubling_cycles(self):
        """ln 2/|ln|mu||: cycles to double (|mu| > 1) or halve (< 1)."""
        g = self.growth_per_cycle
        return math.log(2)/abs(g) if g != 0 else math.inf

    def states(self, names, least=0.05):
        """[(name, |v_i|, phase deg)] of the components of |v_i| >= least,
        largest first."""
        order = np.argsort(-abs(self.vector))
        return [(names[i], float(abs(self.vector[i])),
                 float(np.degrees(np.angle(self.vector[i]))))
                for i in order if abs(self.vector[i]) >= least]


def modes(M, scales):
    """The Modes of the monodromy M (SI states; scales: of the states),
    largest |mu| first; a complex pair's member of arg mu > 0 first."""
    mu, V = np.linalg.eig(M)
    order = sorted(range(len(mu)), key=lambda i: (-abs(mu[i]),
                                                  -np.angle(mu[i])))
    result = []
    for i in order:
        v = V[:, i]/scales
        k = int(np.argmax(abs(v)))
        result.append(Mode(complex(mu[i]), v/v[k]))
    return result


def modal_coordinates(M, differences, mode_index):
    """The coordinate of mode mode_index (in the order of np.linalg.eig
    sorted as modes()) of each state difference (rows)."""
    mu, V = np.linalg.eig(M)
    order = sorted(range(len(mu)), key=lambda i: (-abs(mu[i]),
                                                  -np.angle(mu[i])))
    W = np.linalg.inv(V)
    return np.asarray(differences) @ W[order[mode_index]]


@dataclass
class Floquet:
    """The analysis of a flight: the fixed point x*, its mismatch after a
    cycle (scaled), the monodromy matrix, the modes, the state names and
    scales, the step."""
    x: np.ndarray
    mismatch: float
    M: np.ndarray
    modes: list
    names: list
    scales: np.ndarray
    step: float
    period: float = None

    def unstable(self):
        """The mode of the largest |mu| if it is above 1, else None."""
        return self.modes[0] if self.modes[0].modulus > 1 else None


def analyse(cycle_map, step):
    """The Floquet analysis of the cycle map's case at its initial
    state."""
    layout = cycle_map.layout
    x = cycle_map.initial_state()
    values = cycle_map.values

    def phi(points):
        flights = cycle_map.run_all([(values, p) for p in points])
        return [f.states[1] for f in flights]

    images = phi([x])
    mismatch = float(np.max(abs((images[0] - x)/layout.scales)))
    M = monodromy(phi, x, step*layout.scales)
    return Floquet(x, mismatch, M, modes(M, layout.scales), layout.names,
                   layout.scales, step, cycle_map.period)


def kick(cycle_map, floquet, eps, cycles):
    """The most unstable mode's coordinate ratio per cycle of a flight
    kicked by eps Re(v) (scaled) against the unkicked one: (ratios,
    coordinates)."""
    mode = floquet.modes[0]
    x0 = floquet.x + eps*np.real(mode.vector)*floquet.scales
    kicked, reference = cycle_map.run_all([(cycle_map.values, x0),
                                           (cycle_map.values, floquet.x)],
                                          cycles)
    c = modal_coordinates(floquet.M, kicked.states - reference.states, 0)
    return c[1:]/c[:-1], c


def mode_line(mode, names):
    """The report of one mode."""
    mu = mode.multiplier
    period = mode.period_cycles
    return ("mu = %.6f %+.6fi, |mu| %.6f (ln|mu| %+.5f per cycle): %s;"
            " %s in %.3g cycles; moves %s" % (
                mu.real, mu.imag, mode.modulus, mode.growth_per_cycle,
                "period %.4g cycles" % period if period else "not oscillatory",
                "doubles" if mode.modulus > 1 else "halves",
                mode.doubling_cycles, ", ".join(
                    "%s %.2f (%+.0f deg)" % s for s in mode.states(names))))


def summary(floquet, kick_ratios=None):
    """The Floquet keys of the results' summary.json."""
    unstable = floquet.unstable()
    out = {
        "floquet_multipliers": [[m.multiplier.real, m.multiplier.imag]
                                for m in floquet.modes],
        "floquet_states": floquet.names,
        "floquet_state_scales": floquet.scales.tolist(),
        "floquet_step_scaled": floquet.step,
        "floquet_period_s": floquet.period,
        "floquet_fixed_point_mismatch": floquet.mismatch,
        "floquet_modes": [{
            "multiplier": [m.multiplier.real, m.multiplier.imag],
            "modulus": m.modulus,
            "period_cycles": m.period_cycles,
            "doubling_cycles": m.doubling_cycles,
            "grows": bool(m.modulus > 1),
            "states": m.states(floquet.names)} for m in floquet.modes],
        "unstable_mode_period_cycles":
            unstable.period_cycles if unstable else None,
        "unstable_mode_doubling_cycles":
            unstable.doubling_cycles if unstable else None,
    }
    if kick_ratios is not None:
        out["floquet_kick_ratio_error"] = float(np.max(abs(
            kick_ratios - floquet.modes[0].multiplier))/floquet.modes[0].modulus)
    return out


def plot(path, floquet, kick_coordinates=None):
    """The multipliers against the unit circle, each mode's scaled
    eigenvector, and the kicked flight's modal coordinate."""
    from flapfoam.plots.backend import pyplot
    plt = pyplot()
    panels = 3 if kick_coordinates is not None else 2
    fig, axes = plt.subplots(1, panels, figsize=(5.2*panels, 4.4))
    a = np.linspace(0, 2*np.pi, 2000)
    axes[0].plot(np.cos(a), np.sin(a), "k-", lw=0.8, label="|mu| = 1")
    for i, m in enumerate(floquet.modes):
        axes[0].plot(m.multiplier.real, m.multiplier.imag, "o", ms=8,
                     label="%d: |mu| %.4f%s" % (i, m.modulus, ", T %.3g"
                                                 % m.period_cycles
                                                 if m.period_cycles else ""))
    mu = np.array([m.multiplier for m in floquet.modes])
    half = max(0.15, 1.2*np.max(abs(mu - np.mean(mu.real))))
    axes[0].set_xlim(np.mean(mu.real) - half, np.mean(mu.real) + half)
    axes[0].set_ylim(-half, half)
    axes[0].set_aspect("equal")
    axes[0].set_xlabel("Re mu")
    axes[0].set_ylabel("Im mu")
    axes[0].legend(fontsize=7)
    axes[0].set_title("Floquet multipliers (per cycle)")
    width = 0.8/len(floquet.modes)
    for i, m in enumerate(floquet.modes):
        axes[1].bar(np.arange(len(floquet.names)) + i*width,
                    abs(m.vector), width, label="mode %d" % i)
    axes[1].set_xticks(np.arange(len(floquet.names)) + 0.4 - width/2)
    axes[1].set_xticklabels(floquet.names, rotation=30, fontsize=8)
    axes[1].set_ylabel("|v| (scaled states, largest 1)")
    axes[1].legend(fontsize=7)
    axes[1].set_title("the states each mode moves")
    if kick_coordinates is not None:
        c = kick_coordinates
        k = np.arange(len(c))
        mu = floquet.modes[0].multiplier
        axes[2].semilogy(k, abs(c), "o", label="kicked flight")
        axes[2].semilogy(k, abs(c[0]*mu**k), "-", label="|c_0| |mu|^k")
        axes[2].set_xlabel("cycle")
        axes[2].set_ylabel("|coordinate of mode 0|")
        axes[2].legend(fontsize=8)
        axes[2].set_title("a kick along mode 0")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def arguments(argv):
    parser = argparse.ArgumentParser(
        prog="flapfoam floquet", description=__doc__.split("\n\n")[0])
    parser.add_argument("-case", default=project_path("cases",
                                                      "bodyWingDrone"))
    parser.add_argument("-variant", action="append", default=[])
    parser.add_argument("-edits", metavar="FILE")
    parser.add_argument("-deltaT", dest="delta_t", type=float)
    parser.add_argument("-step", type=float, default=1e-5)
    parser.add_argument("-kick", type=float)
    parser.add_argument("-kickCycles", dest="kick_cycles", type=int,
                        default=4)
    parser.add_argument("-np", type=int, default=1)
    parser.add_argument("-o", metavar="PREFIX")
    parser.add_argument("-summary", metavar="FILE")
    parser.add_argument("-dir", default="/tmp/flapFoam-floquet")
    parser.add_argument("-keep", action="store_true")
    args = parser.parse_args(argv)
    check_ranges(parser, args, ("step", "kick", "delta_t"), ("kick_cycles", "np"))
    return args


def write_outputs(args, floquet, ratios, coordinates):
    """PREFIX.json, PREFIX.png (-o) and the summary's keys (-summary)."""
    keys = summary(floquet, ratios)
    if args.o:
        os.makedirs(os.path.dirname(os.path.abspath(args.o)), exist_ok=True)
        with open(args.o + ".json", "w") as f:
            json.dump(dict(keys, floquet_monodromy=floquet.M.tolist(),
                           floquet_fixed_point=floquet.x.tolist()), f,
                      indent=1)
        plot(args.o + ".png", floquet, coordinates)
        print("floquet: wrote %s.json, %s.png" % (args.o, args.o))
    if args.summary:
        write_summary(args.summary, {k: v for k, v in keys.items()
                                     if k in SUMMARY_KEYS})
        print("floquet: wrote the Floquet keys into %s" % args.summary)


def main(argv=None):
    args = arguments(argv)
    try:
        cycle_map = CycleMap(MapSettings(
            os.path.abspath(args.case), args.variant, args.delta_t,
            os.path.abspath(args.dir), args.np, args.keep,
            read_edits(args.edits) if args.edits else []))
        cycle_map.prepare()
        floquet = analyse(cycle_map, args.step)
        print("floquet: fixed point x* = %s; |Phi(x*) - x*| %.3g (scaled)%s"
              % (" ".join("%s %.9g" % a for a in zip(floquet.names,
                                                     floquet.x)),
                 floquet.mismatch, "" if floquet.mismatch < 1e-6 else
                 ": not a periodic flight (flapfoam trim first)"))
        print("floquet: monodromy matrix by central differences, step %g"
              " (scaled), %d one-cycle runs" % (args.step,
                                                2*len(floquet.names) + 1))
        for i, m in enumerate(floquet.modes):
            print("floquet: mode %d: %s" % (i, mode_line(m, floquet.names)))
        ratios = coordinates = None
        if args.kick:
            ratios, coordinates = kick(cycle_map, floquet, args.kick,
                                       args.kick_cycles)
            mu = floquet.modes[0].multiplier
            print("floquet: kick %g along mode 0: its coordinate per cycle"
                  " over the one before: %s (mu %.6f %+.6fi; largest"
                  " |ratio - mu|/|mu| %.2g)" % (
                      args.kick, ", ".join("%.6f %+.6fi" % (r.real, r.imag)
                                           for r in ratios), mu.real,
                      mu.imag, np.max(abs(ratios - mu))/abs(mu)))
        write_outputs(args, floquet, ratios, coordinates)
    except StudyError as e:
        sys.exit("floquet: %s" % e)


if __name__ == "__main__":
    run_tool(main)
