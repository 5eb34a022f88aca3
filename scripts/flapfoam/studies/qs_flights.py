#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The paper's flights with the quasi-steady wings: the single-wing drone
(SW), the body-wing drone (BW) and its variants Tz and TzRy, N cycles
each (Allrun -model quasiSteady of both cases, no mesh), on one figure.
A figure of two cases, so it lives here, where the cases meet, and the
bench that draws it is bench/quasiSteady (stage flights).

    flapfoam qs_flights [-cycles N] [-dir DIR] [-o PREFIX] [-noRun]

Runs, one after the other, in DIR (default
${TMPDIR:-/tmp}/flapFoam-qsFlights) the folders sw, bw, bw-Tz, bw-TzRy:

    cases/singleWingDrone/Allrun -model quasiSteady -cycles N -clean ...
    cases/bodyWingDrone/Allrun   -model quasiSteady -cycles N -clean
                                 [-variant Tz | -variant TzRy] ...

(-noRun: only read them), and writes (default PREFIX DIR/qsFlights):

  PREFIX-trajectories.png  x(t) and z(t) [mm] of the four against t f
                           (x = q_1, z = q_0: the surge link of SW, the
                           body's centre of mass of BW);
  PREFIX-bodyPitch.png     the body pitch theta = q_2 [deg] of BW and TzRy
                           (Tz holds it at zero);

each legend with the coefficients that flew (each case's defaults: fitted
on its CFD).

Prints each run's wall time and final x, z (and theta).  Exit status
non-zero if a run fails or its flight data are missing.
"""

import argparse
import os
import subprocess
import sys
import time

import numpy as np

from flapfoam.errors import run_tool
from flapfoam.io import flight_data, run_series
from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.paths import project_path
from flapfoam.plots.plotting import cycle_axes, plt, save

# name, case (cases/<case>), Allrun options, legend label, line style (Tz
# dashed: its z(t) lies on TzRy's)
RUNS = [
    ("sw", "singleWingDrone", [], "SW (Tx, Tz)", "-"),
    ("bw", "bodyWingDrone", [], "BW (Tx, Tz, Ry)", "-"),
    ("bw-Tz", "bodyWingDrone", ["-variant", "Tz"], "BW Tz", "--"),
    ("bw-TzRy", "bodyWingDrone", ["-variant", "TzRy"], "BW TzRy", "-"),
]

FREQUENCY = 20.0        # [Hz], the flapping entry of both cases


def run_all(base, cycles):
    """Allrun -model quasiSteady of each run; its wall time [s]."""
    walls = {}
    for name, case, options, _, _ in RUNS:
        folder = os.path.join(base, name)
        command = [project_path("cases", case, "Allrun"), "-model",
                   "quasiSteady", "-cycles", str(cycles), "-clean",
                   "-noPlot", "-case", folder] + options
        t0 = time.time()
        with open(os.path.join(base, "log.%s" % name), "w") as log:
            rc = subprocess.call(command, stdout=log,
                                 stderr=subprocess.STDOUT,
                                 stdin=subprocess.DEVNULL)
        walls[name] = time.time() - t0
        if rc != 0:
            sys.exit("qs_flights: %s failed (exit %d, see %s/log.%s)"
                     % (" ".join(command), rc, base, name))
    return walls


def trajectories(data, prefix):
    """x(t), z(t) of every run on one figure."""
    fig, axes = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for (name, _, _, label, style) in RUNS:
        t, q, model = data[name]
        label = "%s, %s" % (label, model)
        axes[0].plot(FREQUENCY*t, 1e3*q[:, 1], style, label=label)
        axes[1].plot(FREQUENCY*t, 1e3*q[:, 0], style, label=label)
    cycle_axes(axes[0], "x [mm]", "Quasi-steady wings: horizontal position")
    cycle_axes(axes[1], "z [mm]", "Vertical position")
    axes[0].set_xlabel("")
    axes[0].legend(fontsize=7)
    save(fig, *os.path.split(prefix + "-trajectories.png"))


def body_pitch(data, prefix):
    """theta(t) of BW and TzRy."""
    fig, ax = plt.subplots(figsize=(8, 4))
    for (name, _, _, label, _) in RUNS:
        if name in ("bw", "bw-TzRy"):
            t, q, model = data[name]
            ax.plot(FREQUENCY*t, np.degrees(q[:, 2]),
                    label="%s, %s" % (label, model))
    cycle_axes(ax, "theta = q_2 [deg]", "Quasi-steady wings: body pitch")
    ax.legend(fontsize=7)
    save(fig, *os.path.split(prefix + "-bodyPitch.png"))


def read_runs(base, walls):
    """{name: (time, q, model label)} of the runs in base, each printed."""
    data = {}
    for name, _, _, _, _ in RUNS:
        folder = os.path.join(base, name)
        if flight_data.find(folder) is None:
            sys.exit("qs_flights: no flight data in %s" % folder)
        s = run_series.read(folder)
        model = flight_data.model_label(s.attrs, multibody_coeffs(
            os.path.join(folder, "constant", "dynamicMeshDict")))
        data[name] = (s.time, s.q, model)
        t, q = s.time, s.q
        wall = (" in %.2f s" % walls[name]) if name in walls else ""
        pitch = (", theta = %.4g deg" % np.degrees(q[-1, 2])
                 if name.startswith("bw") else "")
        print("qs_flights: %-8s %.4g cycles%s: x = %.5g mm, z = %.5g "
              "mm%s (%s)" % (name, FREQUENCY*(t[-1] - t[0]), wall,
                             1e3*q[-1, 1], 1e3*q[-1, 0], pitch, model))
    return data


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("-cycles", type=int, default=20)
    ap.add_argument("-dir", default=os.path.join(
        os.environ.get("TMPDIR", "/tmp"), "flapFoam-qsFlights"))
    ap.add_argument("-o", dest="prefix", default=None)
    ap.add_argument("-noRun", dest="no_run", action="store_true")
    a = ap.parse_args()
    if a.cycles < 1:
        ap.error("-cycles %d: not allowed (an integer >= 1)" % a.cycles)
    base = os.path.abspath(a.dir)
    prefix = os.path.abspath(a.prefix or os.path.join(base, "qsFlights"))
    os.makedirs(base, exist_ok=True)
    os.makedirs(os.path.dirname(prefix), exist_ok=True)

    data = read_runs(base, {} if a.no_run else run_all(base, a.cycles))
    trajectories(data, prefix)
    body_pitch(data, prefix)
    print("qs_flights: wrote %s-{trajectories,bodyPitch}.png" % prefix)
    return 0


if __name__ == "__main__":
    sys.exit(run_tool(main))
