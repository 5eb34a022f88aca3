# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Plots of a body-wing drone run (Allrun calls it at the end of a run).

    scripts/plotRun.py [-case DIR] [-o OUTDIR]

Reads the run's flight data (postProcessing/flightData/<start>/
flightData.h5, flapfoam.io.flight_data) and writes, in OUTDIR
(default DIR/plots):

  trajectory.png         x-z path of the body's centre of mass [mm];
  bodyPitch.png          body pitch theta = q_2 [deg] against t f;
  forceCoefficients.png  C_xI, C_zI of the wing and of the body (global
                         frame; the flightData coefficients: wing S = R cbar,
                         body S = pi r^2, U_ref = 4 f A_phi R2) against t f,
                         the wing's downstroke (qDot_3 < 0) shaded;
  wingPitchingMoment.png the wing's pitching moment coefficient C_m =
                         M_y/(0.5 rho S U_ref^2 cbar), M about the body's
                         centre of mass, against t f;
  prescribedJoints.png   q_3 (flapping) and q_4 (wing pitching), relative to
                         the body, against the analytic Wang motion of the
                         run's constant/dynamicMeshDict (wang entries);
  stepTimers.png         the step-timer bar chart.

The load of the row of t_k is the one used for the step to t_k, from the
flow at t_{k-1}: it is plotted at t_{k-1} (the start row has none).
Prints a summary.  Exit status non-zero if the data are missing.
"""

import argparse
import os
import sys
from dataclasses import dataclass

import numpy as np

from flapfoam.io import flight_data
from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.plots.plotting import (cycle_axes, path, plt, save, shade_downstrokes,
                               step_timers_chart)
from flapfoam.models.wang import wang_joints


@dataclass
class Run:
    """A run's flight data (attrs, d: {dataset: array}), times t, joints'
    q and qDot, prescribed joints (wang), flapping frequency f, t f and
    the model that flew (flight_data.model_label)."""
    attrs: dict
    d: dict
    t: object
    q: object
    q_dot: object
    wang: dict
    f: float
    tf: object
    model: str


def read_run(case):
    """The run's flight data, Wang joints and model; prints the model."""
    attrs, d = flight_data.load(case)
    t = d["time"]
    coeffs = multibody_coeffs(os.path.join(case, "constant",
                                           "dynamicMeshDict"))
    wang = wang_joints(coeffs)
    f = wang[3].frequency if 3 in wang else 20.0
    model = flight_data.model_label(attrs, coeffs)
    print("plotRun: model %s" % model)
    return Run(attrs, d, t, d["joints/q"], d["joints/qDot"], wang, f, f*t,
               model)


def trajectory(r, out):
    """(a) trajectory of the body."""
    d, t = r.d, r.t
    c = d["bodies/body/position"]
    fig = path(c[:, 0], c[:, 2], t, (
        "x [mm]", "z [mm]",
        "Body-wing drone: path of the body's centre of mass (%s)"
        % r.model))
    save(fig, out, "trajectory.png")
    return c


def body_pitch(r, out):
    """(b) body pitch."""
    q, tf = r.q, r.tf
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(tf, np.degrees(q[:, 2]))
    ax.set_xlabel("t f [cycles]")
    ax.set_ylabel("theta = q_2 [deg]")
    ax.set_title("Body pitch (%s)" % r.model)
    ax.grid(True, alpha=0.3)
    save(fig, out, "bodyPitch.png")


def coefficients(r, out):
    """(c), (d) coefficients at the times of the flow they come from."""
    d, q, q_dot, tf = r.d, r.q, r.q_dot, r.tf
    tl = tf[:-1]
    downstroke = q_dot[:-1, 3] if q.shape[1] > 3 else np.zeros_like(tl)
    fig, ax = plt.subplots(figsize=(8, 4.5))
    shade_downstrokes(ax, tl, downstroke)
    for body in ("wing", "body"):
        C = d["coefficients/" + body][1:]
        ax.plot(tl, C[:, 0], label="%s C_xI" % body)
        ax.plot(tl, C[:, 1], label="%s C_zI" % body)
    cycle_axes(ax, "C = F / (0.5 rho S U_ref^2)",
               "Force coefficients (global frame; %s)" % r.model)
    ax.legend(fontsize=8)
    save(fig, out, "forceCoefficients.png")

    Cm = d["coefficients/wing"][1:, 2]
    fig, ax = plt.subplots(figsize=(8, 4))
    shade_downstrokes(ax, tl, downstroke)
    ax.plot(tl, Cm)
    cycle_axes(ax, "C_m (wing, about the body's centre of mass)",
              "Wing pitching moment")
    save(fig, out, "wingPitchingMoment.png")


def prescribed_joints(r, out):
    """(e) prescribed joints; the largest error over the amplitude."""
    t, q, tf, wang = r.t, r.q, r.tf, r.wang
    worst = 0.0
    fig, axes = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for qi, ev in sorted(wang.items()):
        exact, _, _ = ev(t)
        axes[0].plot(tf, np.degrees(exact), "-", lw=1,
                     label="q_%d analytic" % qi)
        axes[0].plot(tf, np.degrees(q[:, qi]), ".", ms=3,
                     markevery=max(1, len(t)//200), label="q_%d run" % qi)
        err = np.abs(q[:, qi] - exact)
        worst = max(worst, float(err.max())/ev.amplitude)
        axes[1].semilogy(tf, np.maximum(err, 1e-18), label="q_%d" % qi)
    axes[0].set_ylabel("angle [deg]")
    axes[0].legend(fontsize=7)
    axes[1].set_ylabel("|run - analytic| [rad]")
    axes[1].set_xlabel("t f [cycles]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    axes[0].set_title("Prescribed joints (relative to the body)")
    save(fig, out, "prescribedJoints.png")
    return worst


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("-case", default=".")
    ap.add_argument("-o", dest="output", default=None)
    a = ap.parse_args()
    out = a.output or os.path.join(a.case, "plots")
    if flight_data.find(a.case) is None:
        sys.exit("plotRun: no postProcessing/flightData/*/flightData.h5 in %s"
                 % a.case)
    r = read_run(a.case)
    os.makedirs(out, exist_ok=True)         # after the run is found
    c = trajectory(r, out)
    body_pitch(r, out)
    coefficients(r, out)
    worst = prescribed_joints(r, out)

    # (f) step timers
    rc = step_timers_chart(a.case, out, r.attrs.get("case", ""))
    if rc != 0:
        return rc

    t, q = r.t, r.q
    print("plotRun: %d steps, t = %.6g ... %.6g s; body at x = %.6g m, "
          "z = %.6g m, theta = %.6g deg; prescribed joints: max |q - "
          "analytic|/amplitude = %.3g" % (len(t) - 1, t[0], t[-1], c[-1, 0],
                                         c[-1, 2], np.degrees(q[-1, 2]),
                                         worst))
    print("plotRun: wrote %s/{trajectory,bodyPitch,forceCoefficients,"
          "wingPitchingMoment,prescribedJoints,stepTimers}.png" % out)
    return 0
