# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The two-wing drone's 6-DOF flights (cases/twoWingDrone): a CFD flight
beside its quasi-steady (QS) twin, and the manoeuvre variant's, as the
files of its results folder.

    flapfoam two_wing_flight RUN -qs QS [-roll RUN2 -rollQs QS2]
        -o OUTDIR [-f 20] [-maxMB 20]

RUN: the symmetric CFD flight (Allrun -level tiny -cycles 10 -np 2), QS its
QS flight (Allrun -model quasiSteady); RUN2, QS2: the roll variant's.  The
tree's free joints in q order: x, y, z, yaw, pitch, roll (q_0 ... q_5).
Writes in OUTDIR:

  summary.json   (its keys merged into it: other studies' kept) cells,
                 ranks, cycles_run, wall_clock_s (every start of
                 the solver), core_hours_per_cycle_per_million_cells;
                 max_abs_lateral_qs (the largest |y| [m], |yaw|, |roll|
                 [rad] and their rates in the QS flight: 0 if symmetric);
                 max_abs_y_m_cfd, max_abs_roll_deg_cfd,
                 max_abs_yaw_deg_cfd (the CFD flight),
                 symmetry_cfd_by_cycle (its |y|, |yaw|, |roll| bounds to
                 the end of each cycle, the wings' cycle-mean lift
                 difference in %), wing_lift_n_by_cycle (both wings'
                 cycle-mean vertical force [N], CFD and QS); with -roll:
                 roll_rate_deg_per_cycle_cfd/_qs (each whole cycle's mean
                 roll rate) and manoeuvre_rate_deg_per_cycle_cfd/_qs (their
                 mean over the cycles after the first, the start-up)
  trajectory.png x, y, z of the CFD and QS flights
  attitude.png   yaw, pitch, roll of both
  wingForces.png each wing's vertical and horizontal force, both flights
  manoeuvre.png  (-roll) the roll angle and each cycle's roll rate, CFD
                 and QS
  flightData.h5  the CFD flight's flight data, every k-th row under -maxMB

Prints the summary.  numpy, h5py, matplotlib.
"""

import argparse
import os
from dataclasses import dataclass

import numpy as np

from flapfoam.checks.lateral import LATERAL, cycle_rates
from flapfoam.errors import FlapFoamError, run_tool
from flapfoam.io import run_series
from flapfoam.paths import output_folder
from flapfoam.plots.plotting import cycle_axes, plt, save
from flapfoam.studies.ascent import core_hours, n_cells, wall_clock, \
    write_results

STATES = ("x", "y", "z", "yaw", "pitch", "roll")
WINGS = ("leftWing", "rightWing")


@dataclass
class Inputs:
    """The runs, the output folder and the settings of one summary."""
    run: str
    qs: str
    out: str
    roll: str = None
    roll_qs: str = None
    f: float = 20.0
    max_mb: float = 20.0


def read(case):
    """A run's series, checked to be a two-wing tree (6 free joints and
    both wings' loads)."""
    s = run_series.read(case)
    if s.q is None or s.q.shape[1] < 6 or \
            any(w not in s.bodies for w in WINGS):
        raise FlapFoamError("%s: not a two-wing flight (its flight data "
                            "needs joints/q with x y z yaw pitch roll and "
                            "the bodies %s)" % (case, " ".join(WINGS)))
    return s


def lateral_summary(cfd, qs):
    """The symmetric flights' lateral keys."""
    cols = list(LATERAL.values())
    rates = qs.q_dot[:, cols] if qs.q_dot is not None else 0.0
    s = {"max_abs_lateral_qs": float(max(np.abs(qs.q[:, cols]).max(),
                                         np.abs(rates).max())),
         "max_abs_y_m_cfd": float(np.abs(cfd.q[:, LATERAL["y"]]).max())}
    for angle in ("yaw", "roll"):
        s["max_abs_%s_deg_cfd" % angle] = float(
            np.degrees(np.abs(cfd.q[:, LATERAL[angle]]).max()))
    return s


def whole_cycles(time, f):
    """The rows of each whole cycle k = 0, 1, ... of the times (t in
    (k/f, (k + 1)/f]), one boolean mask a cycle."""
    n = int(np.floor(time[-1]*f + 1e-9))
    return [(time > k/f + 1e-12) & (time <= (k + 1)/f + 1e-12)
            for k in range(n)]


def wing_cycle_lifts(run, f):
    """{wing: [its cycle-mean vertical force [N], each whole cycle]}."""
    cycles = whole_cycles(run.time, f)
    return {w: np.array([np.mean(run.bodies[w].force[c, 2])
                         for c in cycles]) for w in WINGS}


def symmetry_by_cycle(cfd, f):
    """The CFD flight's symmetry cycle by cycle (whole cycles k = 1, 2,
    ...): the largest |y| [m], |yaw|, |roll| [deg] from the start to the
    end of cycle k, and the difference of the wings' cycle-mean vertical
    forces in % of their mean."""
    s = {}
    for name, scale in (("y_m", 1.0), ("yaw_deg", 180/np.pi),
                        ("roll_deg", 180/np.pi)):
        bound = np.maximum.accumulate(
            np.abs(cfd.q[:, LATERAL[name.split("_")[0]]]))
        s[name] = [float(scale*bound[c].max())
                   for c in whole_cycles(cfd.time, f)]
    lifts = wing_cycle_lifts(cfd, f)
    left, right = (lifts[w] for w in WINGS)
    s["wing_lift_difference_percent"] = \
        [float(d) for d in 200*(left - right)/(left + right)]
    return s


def wing_lift_by_cycle(runs, f):
    """{label: [the cycle-mean vertical force of both wings [N], each whole
    cycle of the first run]} of the runs [(label, series)]."""
    n = len(whole_cycles(runs[0][1].time, f))
    return {label: [float(v) for v in
                    sum(wing_cycle_lifts(run, f).values())[:n]]
            for label, run in runs}


def manoeuvre_summary(cfd, qs, f):
    """The roll variant's keys: each cycle's roll rate, their mean after
    the first cycle (None where the run has one cycle or none)."""
    s = {}
    for label, run in (("cfd", cfd), ("qs", qs)):
        rates = [round(r, 6) for _, r in cycle_rates(
            run.time, run.q[:, LATERAL["roll"]], f)]
        s["roll_rate_deg_per_cycle_" + label] = rates
        s["manoeuvre_rate_deg_per_cycle_" + label] = \
            float(np.mean(rates[1:])) if len(rates) > 1 else None
    return s


def within(run, first):
    """The rows of run up to the first run's last time (a longer QS
    flight drawn over the CFD flight's cycles)."""
    return run.time <= first.time[-1] + 1e-12


def plot_states(runs, f, names):
    """The states names (indices into STATES) of the runs [(label, series,
    style)] against t f, one panel each, over the first run's times."""
    fig, axes = plt.subplots(len(names), 1, figsize=(8, 2.4*len(names)),
                             sharex=True)
    for label, s, style in runs:
        k = within(s, runs[0][1])
        for ax, i in zip(axes, names):
            scale, unit = (1e3, "mm") if i < 3 else (180/np.pi, "deg")
            ax.plot(s.time[k]*f, scale*s.q[k, i], style, label=label)
            cycle_axes(ax, "%s [%s]" % (STATES[i], unit), "")
    axes[0].legend(fontsize=8)
    axes[0].set_xlim(0, runs[0][1].time[-1]*f)
    return fig


def plot_wing_forces(runs, f, out):
    """Each wing's vertical and horizontal force [mN], both flights, over
    the first one's times."""
    fig, axes = plt.subplots(2, 2, figsize=(11, 6), sharex=True)
    for label, s, style in runs:
        k = within(s, runs[0][1])
        for col, wing in enumerate(WINGS):
            force = s.bodies[wing].force
            for row, (i, name) in enumerate(((2, "F_z"), (0, "F_x"))):
                axes[row][col].plot(s.time[k]*f, 1e3*force[k, i], style,
                                    lw=0.8, label=label)
                cycle_axes(axes[row][col], "%s [mN]" % name,
                           wing if row == 0 else "")
    axes[0][0].legend(fontsize=8)
    axes[0][0].set_xlim(0, runs[0][1].time[-1]*f)
    save(fig, out, "wingForces.png")


def plot_manoeuvre(cfd, qs, s, inputs):
    """The roll variant's roll angle and its per-cycle rates."""
    fig, axes = plt.subplots(2, 1, figsize=(8, 6))
    for label, run, style in (("CFD", cfd, "-"), ("QS", qs, "--")):
        axes[0].plot(run.time*inputs.f,
                     np.degrees(run.q[:, LATERAL["roll"]]), style,
                     label=label)
        rates = s["roll_rate_deg_per_cycle_" + label.lower()]
        axes[1].plot(np.arange(1, len(rates) + 1), rates, "o" + style,
                     label=label)
    cycle_axes(axes[0], "roll [deg]", "Roll variant: roll angle")
    cycle_axes(axes[1], "roll rate [deg/cycle]",
               "each cycle's mean roll rate", "cycle")
    axes[0].legend(fontsize=8)
    save(fig, inputs.out, "manoeuvre.png")


def summarise(inputs):
    """Writes the plots, flightData.h5 and summary.json; the summary."""
    cfd, qs = read(inputs.run), read(inputs.qs)
    cells = n_cells(inputs.run)
    ranks = int(cfd.attrs.get("nRanks", 1))
    wall = wall_clock(inputs.run)
    cycles = float(cfd.time[-1]*inputs.f)
    s = {"run": os.path.abspath(inputs.run), "qs": os.path.abspath(inputs.qs),
         "level": cfd.attrs.get("level"), "cells": cells, "ranks": ranks,
         "cycles_run": round(cycles, 4), "wall_clock_s": round(wall, 1),
         "core_hours_per_cycle_per_million_cells":
             round(core_hours(wall, ranks, cycles, cells), 2)
             if cycles > 0 else None}
    s.update(lateral_summary(cfd, qs))
    s["symmetry_cfd_by_cycle"] = symmetry_by_cycle(cfd, inputs.f)
    s["wing_lift_n_by_cycle"] = wing_lift_by_cycle(
        [("cfd", cfd), ("qs", qs)], inputs.f)
    runs = [("CFD", cfd, "-"), ("QS", qs, "--")]
    save(plot_states(runs, inputs.f, (0, 1, 2)), inputs.out,
         "trajectory.png")
    save(plot_states(runs, inputs.f, (3, 4, 5)), inputs.out,
         "attitude.png")
    plot_wing_forces(runs, inputs.f, inputs.out)
    if inputs.roll:
        roll, roll_qs = read(inputs.roll), read(inputs.roll_qs)
        s.update(manoeuvre_summary(roll, roll_qs, inputs.f))
        s["roll_run"] = os.path.abspath(inputs.roll)
        plot_manoeuvre(roll, roll_qs, s, inputs)
    return write_results(s, inputs.run, inputs.out, inputs.max_mb)


def parse(argv):
    p = argparse.ArgumentParser(prog="flapfoam two_wing_flight",
                                description=__doc__.split("\n\n")[1])
    p.add_argument("run", help="the symmetric CFD flight")
    p.add_argument("-qs", required=True, help="its quasi-steady flight")
    p.add_argument("-roll", help="the roll variant's CFD flight")
    p.add_argument("-rollQs", dest="roll_qs",
                   help="the roll variant's quasi-steady flight")
    p.add_argument("-o", dest="out", required=True)
    p.add_argument("-f", type=float, default=20.0,
                   help="the flapping frequency [Hz] (default 20)")
    p.add_argument("-maxMB", dest="max_mb", type=float, default=20.0)
    a = p.parse_args(argv)
    if bool(a.roll) != bool(a.roll_qs):
        p.error("-roll and -rollQs go together (given: %s)"
                % ("-roll" if a.roll else "-rollQs"))
    if not a.f > 0 or not a.max_mb > 0:
        p.error("-f %g, -maxMB %g: allowed values > 0" % (a.f, a.max_mb))
    return Inputs(a.run, a.qs, a.out, a.roll, a.roll_qs, a.f, a.max_mb)


def main(argv=None):
    inputs = parse(argv)
    output_folder(inputs.out, "two_wing_flight")
    for key, value in summarise(inputs).items():
        print("%s: %s" % (key, value))
    return 0


if __name__ == "__main__":
    run_tool(main)
