# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Plots of a drone run, single-wing, body-wing or two-wing (Allrun calls it
at the end of a run, through the case's scripts/plotRun.py).

    flapfoam plot_drone [-case DIR] [-o OUTDIR] [-dict FILE]
        [-drone singleWing|bodyWing|twoWing]

Reads the run's time series (flapfoam.io.run_series: its flight data, or,
for a run without it, its joints.dat and bodies.dat joined over the run and
its restarts) and its multibody dictionary (-dict, default
DIR/constant/dynamicMeshDict; the drone: -drone, else twoWing if the
dictionary has a body named leftWing, bodyWing if one named body, else
singleWing), and writes in OUTDIR (default DIR/plots):

  trajectory.png         the x-z path [mm]: the single-wing drone's surge
                         link (x = q_1 (Tx), z = q_0 (Tz)), the body-wing
                         drone's body's centre of mass;
  forceCoefficients.png  C_xI, C_zI (global frame) against t f, the
                         downstroke (the flapping joint's qDot < 0)
                         shaded: the single-wing drone's wing from its
                         force, C = F/(0.5 rho S U_ref^2) (below); the
                         other drones' wings and body, the flight data's
                         coefficients (wing S = R cbar, body S = pi r^2);
  prescribedJoints.png   the prescribed joints (the wang entries of the
                         dictionary's imposedMotion) against their analytic
                         Wang motion, and the difference;
  stepTimers.png         the step-timer chart (flapfoam.plots.step_timers
                         on postProcessing/stepTimers);
and the per-case panels (Drone.panels): the body-wing drone's
  bodyPitch.png          the body's pitch theta = q_2 [deg];
  wingPitchingMoment.png the wing's C_m = M_y/(0.5 rho S U_ref^2 cbar), M
                         about the body's centre of mass;
the two-wing drone's
  attitude.png           the body's yaw, pitch and roll (q_3, q_4, q_5)
                         and its y = q_1.

Reference values (docs/paper.md section 3), from the flapping entry and
rhoInf of the dictionary: S = pi/4 c_r R = R cbar (planform area of the
wing); U_ref = 4 f A_phi R2, R2 = sqrt(int c r^2 dr / S) the radius of
gyration of the planform about the flapping axis (r from R0, the root, to
R0 + R, the tip; c = c(r - R0) of flapfoam.models.wing_geometry; for the
semi-ellipse R2^2 = R0^2 + 8/(3 pi) R0 R + R^2/4, R2 = 45.67 mm,
U_ref = 4.783 m/s).

Times: the load of the row of t_k is the one used for the step to t_k,
computed from the flow at t_{k-1}: it is plotted at t_{k-1} (the start row
has none).  Prints a summary (rows, time span, restarts, final position,
the wing's mean coefficients over each complete cycle, the largest
prescribed-joint deviation).  Exit status non-zero if the data are
missing.  numpy, matplotlib (Agg).
"""

import argparse
import math
import os
import sys
from dataclasses import dataclass, field

import numpy as np

from flapfoam.errors import FlapFoamError, run_tool
from flapfoam.io import run_series
from flapfoam.io.flight_data import model_label
from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.models import wing_geometry as geo
from flapfoam.models.wang import wang_joints
from flapfoam.plots.plotting import (cycle_axes, path, plt, save,
                                     shade_downstrokes, step_timers_chart)


@dataclass
class Reference:
    """The prescribed joints ({q index: Wang motion}), rho, the flapping
    frequency f, U_ref, q_ref (dynamic pressure times area) and the q index
    of the flapping joint (None: none)."""
    joints: dict
    rho: float
    f: float
    Uref: float
    qref: float
    flapping: int = None


def reference_values(coeffs):
    """The Reference of the multibody coefficients (the module's
    docstring): the flapping joint is the motion named flapping, else
    joint 2 (the single-wing drone's)."""
    joints = wang_joints(coeffs)
    rho = float(coeffs.get("rhoInf", ["1.2"])[0])
    flapping = next((qi for qi, m in joints.items() if m.name == "flapping"),
                    2 if 2 in joints else None)
    flap = joints.get(flapping)
    f = flap.frequency if flap else 20.0
    Aphi = flap.amplitude if flap else 75.0*math.pi/180.0
    Uref = 4.0*f*Aphi*geo.radius_of_gyration()
    return Reference(joints, rho, f, Uref,
                     0.5*rho*geo.planform_area()*Uref**2, flapping)


def wing_coefficients(series, qref, body="wing"):
    """(t, C_xI, C_zI) of a body's force over qref at the times of the
    flow they come from, t_{k-1} (the row of t_k holds that load)."""
    F = series.bodies[body].force
    return series.time[:-1], F[1:, 0]/qref, F[1:, 2]/qref


@dataclass
class Run:
    """A run's series, its Reference, the model that flew
    (flight_data.model_label) and its name."""
    series: run_series.RunSeries
    ref: Reference
    model: str
    name: str

    @property
    def t(self):
        return self.series.time

    @property
    def f(self):
        return self.ref.f


@dataclass
class Drone:
    """What differs between the drones' plots (the per-case hook): the
    name, the x-z path (path(run) -> x, z, xDot, zDot) with its axis
    labels and title, the coefficients plotted (coefficients(run) ->
    {body: (C_xI, C_zI) at the load times}, {} for none) and the extra
    figures ({PNG name: panel(run, out)})."""
    name: str
    path: object
    path_labels: tuple
    coefficients: object
    panels: dict = field(default_factory=dict)


def surge_link(run):
    """x, z of the single-wing drone's surge link and their rates."""
    q, q_dot = run.series.q, run.series.q_dot
    return q[:, 1], q[:, 0], q_dot[:, 1], q_dot[:, 0]


def body_centre(run):
    """x, z of the body-wing drone's body's centre of mass and their
    rates."""
    body = run.series.bodies["body"]
    return body.position[:, 0], body.position[:, 2], \
        body.velocity[:, 0], body.velocity[:, 2]


def from_force(run):
    """The single-wing drone's wing, from its force and the reference
    values (printed); {} without the wing's force."""
    ref = run.ref
    print("plotRun: S = %.6g m^2, R2 = %.6g m (about the flapping axis; "
          "quadrature %.6g), U_ref = 4 f A_phi R2 = %.6g m/s, rho = %g"
          % (geo.planform_area(), geo.radius_of_gyration(),
             geo.radius_of_gyration_quadrature(), ref.Uref, ref.rho))
    wing = run.series.bodies.get("wing")
    if wing is None or wing.force is None or len(run.t) < 2:
        return {}
    _, cx, cz = wing_coefficients(run.series, ref.qref)
    return {"wing": (cx, cz)}


def flight_data_coefficients(bodies):
    """A drone's loads: the flight data's coefficients C_xI, C_zI of
    bodies (names)."""
    def loads(run):
        out = {}
        for body in bodies:
            b = run.series.bodies.get(body)
            if b is None or b.coefficients is None:
                raise FlapFoamError("plotRun: no coefficients/%s in the "
                                    "flight data of %s (postProcessing/"
                                    "flightData/*/flightData.h5)"
                                    % (body, run.name))
            out[body] = (b.coefficients[1:, 0], b.coefficients[1:, 1])
        return out
    return loads


def downstroke(run):
    """The flapping joint's qDot at the load times (zeros without one)."""
    qi, q_dot = run.ref.flapping, run.series.q_dot
    if qi is None or q_dot is None or q_dot.shape[1] <= qi:
        return np.zeros(len(run.t) - 1)
    return q_dot[:-1, qi]


def body_pitch(run, out):
    """The body-wing drone's body pitch."""
    theta = np.degrees(run.series.q[:, 2])
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(run.f*run.t, theta)
    ax.set_xlabel("t f [cycles]")
    ax.set_ylabel("theta = q_2 [deg]")
    ax.set_title("Body pitch (%s)" % run.model)
    ax.grid(True, alpha=0.3)
    save(fig, out, "bodyPitch.png")
    print("plotRun: final theta = %.6g deg" % theta[-1])


def wing_pitching_moment(run, out):
    """The body-wing drone's wing pitching moment coefficient."""
    tl = run.f*run.t[:-1]
    fig, ax = plt.subplots(figsize=(8, 4))
    shade_downstrokes(ax, tl, downstroke(run))
    ax.plot(tl, run.series.bodies["wing"].coefficients[1:, 2])
    cycle_axes(ax, "C_m (wing, about the body's centre of mass)",
               "Wing pitching moment")
    save(fig, out, "wingPitchingMoment.png")


def attitude(run, out):
    """The two-wing drone's body attitude, yaw, pitch and roll (q_3, q_4,
    q_5), and its y."""
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


BODY_PATH = ("x [mm]", "z [mm]", "path of the body's centre of mass")

DRONES = {
    "singleWing": Drone(
        "Single-wing drone", surge_link,
        ("x = q_1 (Tx) [mm]", "z = q_0 (Tz) [mm]",
         "trajectory of the surge link"), from_force),
    "bodyWing": Drone(
        "Body-wing drone", body_centre, BODY_PATH,
        flight_data_coefficients(("wing", "body")),
        {"bodyPitch": body_pitch,
         "wingPitchingMoment": wing_pitching_moment}),
    "twoWing": Drone(
        "Two-wing drone", body_centre, BODY_PATH,
        flight_data_coefficients(("leftWing", "rightWing", "body")),
        {"attitude": attitude}),
}


def source_label(series):
    """What the series were read from, in a few words."""
    if series.from_flight_data:
        return "flightData.h5"
    return "%s joints.dat" % os.path.basename(series.source)


def read_run(case, coeffs):
    """The run's Run (coeffs: its multibody coefficients); prints what it
    read."""
    ref = reference_values(coeffs)
    series = run_series.read(case)
    t = series.time
    print("plotRun: reading %s" % series.source)
    print("plotRun: %d rows after the first (the written steps), t = %.6g"
          " ... %.6g s (%.6g cycles), %d restart folder(s)"
          % (len(t) - 1, t[0], t[-1], (t[-1] - t[0])*ref.f,
             max(len(series.starts) - 1, 0)))
    model = model_label(series.attrs, coeffs)
    print("plotRun: model %s" % model)
    return Run(series, ref, model, series.attrs.get("case") or
               os.path.basename(os.path.abspath(case)))


def trajectory(run, drone, out):
    """The x-z path; prints its end."""
    x, z, x_dot, z_dot = drone.path(run)
    xlabel, zlabel, title = drone.path_labels
    fig = path(x, z, run.t, (xlabel, zlabel, "%s: %s (%s)"
                             % (drone.name, title, run.model)), lw=1.2)
    save(fig, out, "trajectory.png")
    print("plotRun: final x = %.6g m, z = %.6g m, xDot = %.6g, zDot = %.6g "
          "m/s" % (x[-1], z[-1], x_dot[-1], z_dot[-1]))


def clip_range(curves):
    """The impulsive start (the flow at rest, the wing at full speed with
    -midStroke) gives coefficients of order 1e3 for a few steps: the range
    shown, (low, high), is that of every body's (curves: {body: (C_xI,
    C_zI)}) median +- 10 scaled median absolute deviations (at least its
    2-98 percentile range) when the spikes would hide the rest (with a
    5 % margin), else None."""
    lo, hi = np.inf, -np.inf
    for pair in curves.values():
        values = np.concatenate(pair)
        med = np.median(values)
        spread = 10*1.4826*np.median(np.abs(values - med)) + 1e-12
        p2, p98 = np.percentile(values, [2, 98])
        lo, hi = min(lo, med - spread, p2), max(hi, med + spread, p98)
    values = np.concatenate([c for pair in curves.values() for c in pair])
    if len(values) > 40*len(curves) and \
            (values.min() < lo or values.max() > hi):
        pad = 0.05*(hi - lo)
        return lo - pad, hi + pad
    return None


def force_coefficients(run, drone, curves, out):
    """The coefficients ({body: (C_xI, C_zI)}) at the load times; prints
    their ranges, the wing's cycle means (and the drone's path at the
    cycles' ends) and last values."""
    tl = run.f*run.t[:-1]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    shade_downstrokes(ax, tl, downstroke(run))
    for body, (cx, cz) in curves.items():
        ax.plot(tl, cx, label="%s C_xI" % body)
        ax.plot(tl, cz, label="%s C_zI" % body)
        print("plotRun: %s C_xI from %.4g to %.4g, C_zI from %.4g to %.4g"
              % (body, cx.min(), cx.max(), cz.min(), cz.max()))
    clipped = clip_range(curves)
    if clipped:
        values = np.concatenate([c for pair in curves.values() for c in pair])
        ax.set_ylim(*clipped)
        ax.text(0.01, 0.01, "range clipped: C from %.3g to %.3g"
                % (values.min(), values.max()), transform=ax.transAxes,
                fontsize=8, va="bottom")
    cycle_axes(ax, "C = F / (0.5 rho S U_ref^2)",
               "Force coefficients (global frame; %s)" % run.model,
               "t f [cycles]; each load drawn at the row before its own"
               " (CFD: the flow it comes from, docs/flightData.md)")
    ax.legend(fontsize=8)
    save(fig, out, "forceCoefficients.png")
    if "wing" in curves:
        cx, cz = curves["wing"]
        cycles, overall = cycle_means(run, (cx, cz), drone.path(run)[:2])
        for row in cycles:
            print("plotRun: cycle %d: mean C_xI = %.6g, C_zI = %.6g; at its "
                  "end x = %.6g m, z = %.6g m" % row)
        if overall:
            print("plotRun: mean C_xI = %.6g, C_zI = %.6g over %d cycle(s)"
                  % overall)
        print("plotRun: last C_xI = %.6g, C_zI = %.6g" % (cx[-1], cz[-1]))


def cycle_means(run, c, x_z):
    """([(k, mean C_xI, mean C_zI, x, z)] of each whole cycle k of the run
    that has loads, (the means over the n whole cycles, n) or None): the
    means of c (C_xI, C_zI at the load times) weighted by the steps, the
    path x_z at the cycle's end.  The run's end time decides which cycles
    are whole (the load of the last step comes from the flow one step
    earlier)."""
    t, f = run.t, run.f
    (cx, cz), (x, z) = c, x_z
    t_load = t[:-1]
    n_cycles = int(math.floor((t[-1] - t[0])*f + 1e-9))
    w = np.diff(t)                  # the step each load acted over

    def mean(v, sel):
        return np.sum(w[sel]*v[sel])/np.sum(w[sel])
    cycles = []
    for k in range(1, n_cycles + 1):
        sel = (t_load >= t[0] + (k - 1)/f - 1e-12) & \
            (t_load < t[0] + k/f - 1e-12)
        if sel.any():
            end = t[0] + k/f
            cycles.append((k, mean(cx, sel), mean(cz, sel),
                           np.interp(end, t, x), np.interp(end, t, z)))
    if n_cycles < 1:
        return cycles, None
    sel = t_load < t[0] + n_cycles/f - 1e-12
    return cycles, (mean(cx, sel), mean(cz, sel), n_cycles)


def prescribed_joints(run, out):
    """The prescribed joints against their analytic motion; prints and
    returns the largest error over the amplitude."""
    t, f, q = run.t, run.f, run.series.q
    worst = 0.0
    fig, axes = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for qi, ev in sorted(run.ref.joints.items()):
        exact, _, _ = ev(t)
        label = "q_%d %s" % (qi, ev.name)
        axes[0].plot(f*t, np.degrees(exact), "-", lw=1,
                     label=label + " analytic")
        axes[0].plot(f*t, np.degrees(q[:, qi]), ".", ms=3,
                     markevery=max(1, len(t)//200), label=label + " run")
        err = np.abs(q[:, qi] - exact)
        worst = max(worst, float(err.max())/ev.amplitude)
        axes[1].semilogy(f*t, np.maximum(err, 1e-18), lw=1,
                         label="|q_%d - analytic|" % qi)
    axes[0].set_ylabel("angle [deg]")
    axes[0].legend(fontsize=7)
    axes[1].set_ylabel("|run - analytic| [rad]")
    axes[1].set_xlabel("t f [cycles]")
    axes[1].legend(fontsize=7)
    for ax in axes:
        ax.grid(True, alpha=0.3)
    axes[0].set_title("Prescribed joints against the Wang kinematics (%s)"
                      % source_label(run.series))
    save(fig, out, "prescribedJoints.png")
    print("plotRun: prescribed joints: max |q - analytic|/amplitude = %.3g"
          % worst)
    return worst


def plot(run, drone, out):
    """Every figure of the run but the step timers' in out (made once the
    drone's coefficients are there); the names written."""
    curves = drone.coefficients(run)        # may fail: before any figure
    os.makedirs(out, exist_ok=True)
    written = ["trajectory"]
    trajectory(run, drone, out)
    if curves:
        force_coefficients(run, drone, curves, out)
        written.append("forceCoefficients")
    for name, panel in drone.panels.items():
        panel(run, out)
        written.append(name)
    if run.ref.joints:
        prescribed_joints(run, out)
        written.append("prescribedJoints")
    return written


def default_drone(bodies):
    """The drone of a dictionary's bodies (names)."""
    if "leftWing" in bodies:
        return "twoWing"
    return "bodyWing" if "body" in bodies else "singleWing"


def main(argv=None, drone=None):
    ap = argparse.ArgumentParser(prog="flapfoam plot_drone",
                                 description=__doc__.split("\n")[1],
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("-case", default=".", help="the run folder")
    ap.add_argument("-o", dest="output", default=None,
                    help="output directory (default CASE/plots; a relative "
                         "path is relative to the working directory)")
    ap.add_argument("-dict", default=None,
                    help="multibody dictionary (default "
                         "CASE/constant/dynamicMeshDict)")
    ap.add_argument("-drone", choices=sorted(DRONES), default=drone,
                    help="the drone (default: twoWing if the dictionary "
                         "has a body named leftWing, bodyWing if one named "
                         "body, else singleWing)")
    a = ap.parse_args(argv)
    out = a.output or os.path.join(a.case, "plots")
    dict_path = a.dict or os.path.join(a.case, "constant", "dynamicMeshDict")
    if not os.path.isfile(dict_path):
        raise FlapFoamError("plotRun: no %s (-case: a run folder)"
                            % dict_path)
    coeffs = multibody_coeffs(dict_path)
    run = read_run(a.case, coeffs)
    name = a.drone or default_drone(coeffs.get("bodies", {}))
    written = plot(run, DRONES[name], out)
    rc = step_timers_chart(a.case, out, run.name)
    if rc != 0:
        print("plotRun: the step-timer chart failed (exit %d)" % rc)
        return rc
    if os.path.isfile(os.path.join(out, "stepTimers.png")):
        written.append("stepTimers")
    print("plotRun: wrote %s/{%s}.png" % (out, ",".join(written)))
    return 0


if __name__ == "__main__":
    sys.exit(run_tool(main))
