#!/usr/bin/python3
# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The paper's flights with the quasi-steady wings: the single-wing drone
(SW), the body-wing drone (BW) and its variants Tz and TzRy, N cycles
each (Allrun -model quasiSteady of both cases, no mesh), on one figure.

    scripts/plotQuasiSteady.py [-cycles N] [-dir DIR] [-o OUTDIR] [-noRun]

Runs, one after the other, in DIR (default runs/quasiSteadyPaper of this
case) the folders sw, bw, bw-Tz, bw-TzRy:

    cases/singleWingDrone/Allrun -model quasiSteady -cycles N -clean ...
    cases/bodyWingDrone/Allrun   -model quasiSteady -cycles N -clean
                                 [-variant Tz | -variant TzRy] ...

(-noRun: only read them), and writes in OUTDIR (default DIR):

  quasiSteadyTrajectories.png  x(t) and z(t) [mm] of the four against t f
                               (x = q_1, z = q_0: the surge link of SW, the
                               body's centre of mass of BW);
  quasiSteadyBodyPitch.png     the body pitch theta = q_2 [deg] of BW and
                               TzRy (Tz holds it at zero);

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

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.dirname(HERE)
from flapfoam.io import flight_data, run_series
from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.plots.plotting import cycle_axes, plt, save

# name, case folder, Allrun options, legend label, line style (Tz dashed:
# its z(t) lies on TzRy's)
RUNS = [
    ("sw", "../singleWingDrone", [], "SW (Tx, Tz)", "-"),
    ("bw", ".", [], "BW (Tx, Tz, Ry)", "-"),
    ("bw-Tz", ".", ["-variant", "Tz"], "BW Tz", "--"),
    ("bw-TzRy", ".", ["-variant", "TzRy"], "BW TzRy", "-"),
]

FREQUENCY = 20.0        # [Hz], the flapping entry of both cases


def run_all(base, cycles):
    """Allrun -model quasiSteady of each run; its wall time [s]."""
    walls = {}
    for name, case, options, _, _ in RUNS:
        folder = os.path.join(base, name)
        command = [os.path.join(CASE, case, "Allrun"), "-model",
                   "quasiSteady", "-cycles", str(cycles), "-clean",
                   "-noPlot", "-case", folder] + options
        t0 = time.time()
        with open(os.path.join(base, "log.%s" % name), "w") as log:
            rc = subprocess.call(command, stdout=log,
                                 stderr=subprocess.STDOUT,
                                 stdin=subprocess.DEVNULL)
        walls[name] = time.time() - t0
        if rc != 0:
            sys.exit("plotQuasiSteady: %s failed (exit %d, see %s/log.%s)"
                     % (" ".join(command), rc, base, name))
    return walls


def trajectories(data, out):
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
    save(fig, out, "quasiSteadyTrajectories.png")


def body_pitch(data, out):
    """theta(t) of BW and TzRy."""
    fig, ax = plt.subplots(figsize=(8, 4))
    for (name, _, _, label, _) in RUNS:
        if name in ("bw", "bw-TzRy"):
            t, q, model = data[name]
            ax.plot(FREQUENCY*t, np.degrees(q[:, 2]),
                    label="%s, %s" % (label, model))
    cycle_axes(ax, "theta = q_2 [deg]", "Quasi-steady wings: body pitch")
    ax.legend(fontsize=7)
    save(fig, out, "quasiSteadyBodyPitch.png")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("-cycles", type=int, default=20)
    ap.add_argument("-dir", default=os.path.join(CASE, "runs",
                                                 "quasiSteadyPaper"))
    ap.add_argument("-o", dest="output", default=None)
    ap.add_argument("-noRun", dest="no_run", action="store_true")
    a = ap.parse_args()
    if a.cycles < 1:
        ap.error("-cycles %d: not allowed (an integer >= 1)" % a.cycles)
    base = os.path.abspath(a.dir)
    out = a.output or base
    os.makedirs(base, exist_ok=True)
    os.makedirs(out, exist_ok=True)

    walls = {} if a.no_run else run_all(base, a.cycles)
    data = {}
    for name, _, _, _, _ in RUNS:
        folder = os.path.join(base, name)
        if flight_data.find(folder) is None:
            sys.exit("plotQuasiSteady: no flight data in %s" % folder)
        s = run_series.read(folder)
        model = flight_data.model_label(s.attrs, multibody_coeffs(
            os.path.join(folder, "constant", "dynamicMeshDict")))
        data[name] = (s.time, s.q, model)
        t, q, _ = data[name]
        wall = (" in %.2f s" % walls[name]) if name in walls else ""
        pitch = (", theta = %.4g deg" % np.degrees(q[-1, 2])
                 if name.startswith("bw") else "")
        print("plotQuasiSteady: %-8s %.4g cycles%s: x = %.5g mm, z = %.5g "
              "mm%s (%s)" % (name, FREQUENCY*(t[-1] - t[0]), wall,
                             1e3*q[-1, 1], 1e3*q[-1, 0], pitch, model))
    trajectories(data, out)
    body_pitch(data, out)
    print("plotQuasiSteady: wrote %s/quasiSteady{Trajectories,BodyPitch}.png"
          % out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
