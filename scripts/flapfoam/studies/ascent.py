# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The production ascents (the paper's 20-cycle free flights): a run's results
beside the paper's, as files anyone can check.

    flapfoam ascent RUN -o OUTDIR [-vacuum DIR] [-qs DIR]
        [-maxMB 20]

RUN is a drone run folder (Allrun -cycles 20, restarted any number of
times); -vacuum DIR a run of the same dictionaries without air load
(rigidBodySimulate -bodyLoad vacuum), -qs DIR the quasi-steady model's run
(Allrun -model quasiSteady).  Writes in OUTDIR:

  summary.json     (its keys merged into it) cells, ranks, cycles_run,
                   end_time, wall_clock_s (the
                   solver logs' ClockTime, every start, the work a kill
                   lost included), core_hours_per_cycle_per_million_cells
                   (and the paper's, 96), pitch_deg_at_cycle_end (the body
                   pitch q_2 at t = k/f, k = 1..cycles), lev_volume_percent
                   and lev_circulation_percent (the levStatistics rows at
                   t' = 0.75, 9.75, 18.75 cycles relative to the first;
                   null where the run has no row), with -qs max_abs_dx_m and
                   max_abs_dz_m (the run's x = q_1, z = q_0 against the
                   model's over the run), and the paper's figures;
  trajectory.png   x(t) and z(t) (q_1, q_0), the QS run beside, the vacuum
                   run in x (in z it falls freely);
  bodyPitch.png    q_2 [deg] against t f, the cycle ends marked, the other
                   runs beside (BW);
  liftCycles.png   the wing's C_zI over cycles 2, 5, 10, 17 (the load of a
                   row plotted at the time of the flow it comes from);
  wingCoefficients.png  the wing's C_xI and C_zI over the whole run, the QS
                   run's beside (the paper's figures 10 and 11);
  lev.png          V' and Gamma over the written times, relative to t' =
                   0.75;
  flightData.h5    the run's flight data, every row, or every k-th row so
                   that it stays under -maxMB (k in its attribute thinning).

Prints the summary.  numpy, h5py, matplotlib.
"""

import argparse
import glob
import os
import re
from dataclasses import dataclass

import numpy as np

from flapfoam.io import flight_data, run_series
from flapfoam.plots.plotting import cycle_axes, plt, save
from flapfoam.io.tables import joined_table
from flapfoam.errors import run_tool
from flapfoam.paths import output_folder
from flapfoam.studies.qs_case import write_summary

PAPER = {
    "core_hours_per_cycle_per_million_cells": 96.0,
    "lev_volume_percent": [100, 99, 92],
    "lev_circulation_percent": [100, 92, 90],
    "lev_phases_cycles": [0.75, 9.75, 18.75],
    "max_abs_dx_m": 0.04,
    "max_abs_dz_m": 0.10,
    "lift_cycles": [2, 5, 10, 17],
    "source": "Poletti et al., sections 5.2 and 6; shared/REFERENCE.md 4",
}
LOG = "log.overPimpleDyMFoam"


@dataclass
class Flight:
    """A run's flight data: times, joints' q (x = q_1, z = q_0, pitch q_2
    where there is one), the wing's coefficients, the frequency f."""
    t: np.ndarray
    q: np.ndarray
    c_wing: np.ndarray
    f: float
    attrs: dict


def read_flight(case, f=20.0):
    """The flight data of a run folder."""
    s = run_series.read(case)
    wing = s.bodies.get("wing")
    c = wing.coefficients if wing and wing.coefficients is not None \
        else np.zeros((len(s.time), 3))
    return Flight(s.time, s.q, c, f, s.attrs)


def at_cycle_ends(t, y, f):
    """y at t = k/f for the whole cycles k = 1, 2, ... that t covers."""
    n = int(np.floor(t[-1]*f + 1e-9))
    ends = np.arange(1, n + 1)/f
    return np.interp(ends, t, y)


def lev_table(case):
    """(t, volume, circulation) of the run's levStatistics rows, every
    start joined (postProcessing/<name>/<start>/levStatistics.dat)."""
    rows = []
    for base in sorted(glob.glob(os.path.join(case, "postProcessing", "*"))):
        if glob.glob(os.path.join(base, "*", "levStatistics.dat")):
            _, data = joined_table(base, "levStatistics.dat", False)
            rows.append(data[:, :3])
    if not rows:
        return np.zeros((0, 3))
    data = np.vstack(rows)
    return data[np.argsort(data[:, 0], kind="stable")]


def lev_relative(lev, f, phases):
    """V' and Gamma at t = phase/f (a row within 1e-6 s) in percent of the
    first phase's; None where there is no row (or no first row)."""
    def at(phase):
        hit = np.flatnonzero(np.abs(lev[:, 0] - phase/f) < 1e-6)
        return lev[hit[-1], 1:3] if hit.size else None
    values = [at(p) for p in phases]
    if values[0] is None:
        return [None]*len(phases), [None]*len(phases)
    return tuple([None if v is None else round(100*v[i]/values[0][i], 2)
                  for v in values] for i in (0, 1))


def wall_clock(case):
    """Seconds of wall-clock of the solver over every start: the last
    ClockTime of each solver log of the run (log.overPimpleDyMFoam,
    log.overPimpleDyMFoam.<time>, previous/ copies), summed."""
    total = 0.0
    logs = glob.glob(os.path.join(case, LOG + "*")) + \
        glob.glob(os.path.join(case, "previous", LOG + "*"))
    clock = re.compile(r"ClockTime = (\S+) s")
    for path in logs:
        last = 0.0
        with open(path, errors="replace") as fh:
            for line in fh:
                m = clock.search(line)
                if m:
                    last = float(m.group(1))
        total += last
    return total


def n_cells(case):
    """The mesh's cells (the note of constant/polyMesh/owner)."""
    with open(os.path.join(case, "constant", "polyMesh", "owner"),
              errors="replace") as fh:
        m = re.search(r"nCells:\s*(\d+)", fh.read(4000))
    if not m:
        raise ValueError("%s/constant/polyMesh/owner has no nCells note"
                         % case)
    return int(m.group(1))


def core_hours(wall_s, ranks, cycles, cells):
    """Core-hours per simulated cycle per million cells."""
    return wall_s*ranks/3600.0/cycles/(cells/1e6)


def max_gaps(run, model):
    """max |x - x_model|, max |z - z_model| over the run's times (x = q_1,
    z = q_0; the model interpolated at the run's times within its own)."""
    keep = run.t <= model.t[-1] + 1e-12
    t = run.t[keep]
    dx = run.q[keep, 1] - np.interp(t, model.t, model.q[:, 1])
    dz = run.q[keep, 0] - np.interp(t, model.t, model.q[:, 0])
    return float(np.max(np.abs(dx))), float(np.max(np.abs(dz)))


def thin_copy(src, dst, max_bytes):
    """Copy the flight data file src to dst, every k-th row (k the
    smallest that keeps the rows under max_bytes; the last row kept);
    returns k."""
    import h5py
    with h5py.File(src, "r") as fin:
        n = len(fin["time"])
        row_bytes = 0
        datasets = {}

        def visit(name, obj):
            nonlocal row_bytes
            if isinstance(obj, h5py.Dataset) and obj.shape and \
                    obj.shape[0] >= n:
                datasets[name] = obj
                row_bytes += obj[0:1].nbytes
        fin.visititems(visit)
        k = max(1, int(np.ceil(n*row_bytes/max_bytes)))
        rows = np.unique(np.append(np.arange(0, n, k), n - 1))
        with h5py.File(dst, "w") as fout:
            for key, value in fin.attrs.items():
                fout.attrs[key] = value
            fout.attrs["thinning"] = "every %d-th row of %d (and the last)" \
                % (k, n) if k > 1 else "every row"
            for name, obj in datasets.items():
                out = fout.create_dataset(name, data=obj[:n][rows],
                                          compression="gzip")
                for key, value in obj.attrs.items():
                    out.attrs[key] = value
    return k


def plot_trajectory(run, others, out):
    """x(t), z(t) of the run and of the other runs (label, Flight, style);
    the vacuum run in x only (in z it falls freely, as the paper's figure
    leaves it out)."""
    fig, axes = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for label, flight, style in [("CFD", run, "-")] + others:
        for ax, i in zip(axes, (1, 0)):
            if label == "vacuum" and i == 0:
                continue
            ax.plot(flight.t*run.f, 1e3*flight.q[:, i], style, label=label)
    cycle_axes(axes[0], "x = q_1 [mm]", "Ascent: trajectory")
    cycle_axes(axes[1], "z = q_0 [mm]", "")
    axes[0].legend(fontsize=8)
    save(fig, out, "trajectory.png")


def plot_pitch(run, others, out):
    """The body pitch q_2 and its values at the cycle ends, the other runs'
    beside (the paper's figure: the vacuum run dash-dotted)."""
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(run.t*run.f, np.degrees(run.q[:, 2]), label="CFD")
    for label, flight, style in others:
        ax.plot(flight.t*run.f, np.degrees(flight.q[:, 2]), style,
                label=label)
    ends = at_cycle_ends(run.t, np.degrees(run.q[:, 2]), run.f)
    ax.plot(np.arange(1, len(ends) + 1), ends, "o", label="cycle ends")
    cycle_axes(ax, "theta = q_2 [deg]", "Body pitch")
    ax.legend(fontsize=8)
    save(fig, out, "bodyPitch.png")


def lift_peaks(run, cycles, window=0.01):
    """{cycle: [peak C_zI of its first half, of its second half]} of the
    wing, C_zI averaged over window of a cycle (a moving mean over the
    steps: the tiny mesh's forces are noisy), at the times of the flow
    (the row of t_k holds the load of t_{k-1}); the cycles the run covers
    whole."""
    tf = run.t[:-1]*run.f
    cz = run.c_wing[1:, 1]
    peaks = {}
    for n in cycles:
        inside = (tf >= n - 1) & (tf <= n)
        if not inside.any() or tf[-1] < n - 1e-9:
            continue
        phase, c = tf[inside] - (n - 1), cz[inside]
        # the mean of the rows within window/2 of each row (phase sorted)
        total = np.concatenate([[0.0], np.cumsum(c)])
        lo = np.searchsorted(phase, phase - window/2, side="left")
        hi = np.searchsorted(phase, phase + window/2, side="right")
        mean = (total[hi] - total[lo])/(hi - lo)
        peaks[n] = [round(float(mean[half].max()), 3) for half in
                    (phase < 0.5, phase >= 0.5)]
    return peaks


def plot_lift_cycles(run, cycles, out):
    """The wing's C_zI over each cycle of cycles that the run covers."""
    fig, ax = plt.subplots(figsize=(8, 4.5))
    tf = run.t[:-1]*run.f
    cz = run.c_wing[1:, 1]
    for n in cycles:
        inside = (tf >= n - 1) & (tf <= n)
        if inside.any():
            ax.plot(tf[inside] - (n - 1), cz[inside], label="cycle %d" % n)
    cycle_axes(ax, "wing C_zI", "Lift of the wing in cycles %s"
               % ", ".join(map(str, cycles)))
    ax.set_xlabel("t f - (cycle - 1)")
    ax.legend(fontsize=8)
    save(fig, out, "liftCycles.png")


def plot_coefficients(run, others, out):
    """The wing's C_xI and C_zI against t f, the CFD's (a row's load at the
    time of the flow it comes from) and the QS run's (its own times)."""
    fig, axes = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
    curves = [("CFD", run.t[:-1], run.c_wing[1:])]
    curves += [(label, flight.t, flight.c_wing)
               for label, flight, style in others if label == "QS"]
    for label, t, c in curves:
        for ax, i in zip(axes, (0, 1)):
            ax.plot(t*run.f, c[:, i], lw=0.6, label=label)
    cycle_axes(axes[0], "wing C_xI", "The wing's force coefficients")
    cycle_axes(axes[1], "wing C_zI", "")
    axes[0].legend(fontsize=8)
    save(fig, out, "wingCoefficients.png")


def plot_lev(lev, f, out):
    """V' and Gamma over the written times, relative to the first row at
    or after t' = 0.75."""
    if len(lev) == 0:
        return
    first = lev[np.argmax(lev[:, 0] >= 0.75/f - 1e-6)]
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(lev[:, 0]*f, 100*lev[:, 1]/first[1], ".-", label="V'")
    ax.plot(lev[:, 0]*f, 100*lev[:, 2]/first[2], ".-", label="Gamma")
    cycle_axes(ax, "% of t f = 0.75", "Leading-edge vortex (levStatistics)")
    ax.legend(fontsize=8)
    save(fig, out, "lev.png")


@dataclass
class Inputs:
    """The runs and the output of one summary."""
    run: str
    out: str
    vacuum: str = None
    qs: str = None
    max_mb: float = 20.0


def summarise(inputs):
    """Write the plots, flightData.h5 and summary.json; return the
    summary."""
    run = read_flight(inputs.run)
    others = []
    for label, case, style in (("vacuum", inputs.vacuum, "--"),
                               ("QS", inputs.qs, ":")):
        if case:
            others.append((label, read_flight(case), style))
    cells = n_cells(inputs.run)
    ranks = int(run.attrs.get("nRanks", 1))
    wall = wall_clock(inputs.run)
    cycles = run.t[-1]*run.f
    lev = lev_table(inputs.run)
    vol, circ = lev_relative(lev, run.f, PAPER["lev_phases_cycles"])
    s = {"run": os.path.abspath(inputs.run), "case": run.attrs.get("case"),
         "level": run.attrs.get("level"), "cells": cells, "ranks": ranks,
         "cycles_run": round(float(cycles), 4), "end_time": float(run.t[-1]),
         "steps": int(len(run.t) - 1), "wall_clock_s": round(wall, 1),
         "core_hours_per_cycle_per_million_cells":
             round(core_hours(wall, ranks, cycles, cells), 2),
         "lev_volume_percent": vol, "lev_circulation_percent": circ,
         "paper": PAPER}
    if run.q.shape[1] > 4:
        s["pitch_deg_at_cycle_end"] = [
            round(float(v), 4) for v in
            at_cycle_ends(run.t, np.degrees(run.q[:, 2]), run.f)]
        plot_pitch(run, others, inputs.out)
    if inputs.qs:
        s["max_abs_dx_m"], s["max_abs_dz_m"] = max_gaps(run, others[-1][1])
    plot_trajectory(run, others, inputs.out)
    s["lift_peaks_CzI"] = lift_peaks(run, PAPER["lift_cycles"])
    covered = [n for n in PAPER["lift_cycles"] if n in s["lift_peaks_CzI"]]
    if covered:
        plot_lift_cycles(run, covered, inputs.out)
    else:
        print("ascent: no liftCycles.png and no lift peaks: the run ends at"
              " cycle %.3g, before the end of cycle %d, the first of the"
              " paper's lift cycles (%s)"
              % (run.t[-1]*run.f, PAPER["lift_cycles"][0],
                 ", ".join(map(str, PAPER["lift_cycles"]))))
    plot_coefficients(run, others, inputs.out)
    plot_lev(lev, run.f, inputs.out)
    return write_results(s, inputs.run, inputs.out, inputs.max_mb)


def write_results(s, run, out, max_mb):
    """The run's flight data thinned to max_mb into out/flightData.h5 (s
    gets flight_data_thinning), then s merged into out/summary.json (the
    keys of other studies there kept); s."""
    s["flight_data_thinning"] = thin_copy(
        flight_data.find(run), os.path.join(out, "flightData.h5"),
        max_mb*1e6)
    write_summary(os.path.join(out, "summary.json"), s)
    return s


def main(argv=None):
    p = argparse.ArgumentParser(
        prog="flapfoam ascent",
        description="A production ascent's plots, flight data and "
                    "summary.json beside the paper's figures")
    p.add_argument("run", help="the CFD run folder (its flight data)")
    p.add_argument("-o", dest="out", required=True,
                   help="the results folder (made if it does not exist)")
    p.add_argument("-vacuum", help="a vacuum run of the same case: its"
                   " trajectory beside")
    p.add_argument("-qs", help="a quasi-steady run of the same case: its"
                   " trajectory beside, the largest gaps")
    p.add_argument("-maxMB", dest="max_mb", type=float, default=20.0,
                   help="the copied flight data's largest size [MB] (rows"
                   " thinned to it; default 20)")
    a = p.parse_args(argv)
    output_folder(a.out, "ascent")
    s = summarise(Inputs(a.run, a.out, a.vacuum, a.qs, a.max_mb))
    for key, value in s.items():
        if key not in ("paper",):
            print("%s: %s" % (key, value))


if __name__ == "__main__":
    run_tool(main)
