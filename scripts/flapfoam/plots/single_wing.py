# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Plots of a single-wing drone run (Allrun calls it at the end of a run).

    scripts/plotRun.py [-case DIR] [-o OUTDIR] [-dict FILE]

Reads the run's flight data, postProcessing/flightData/<start>/flightData.h5
(flapfoam.io.flight_data; restarts append to it), or, for runs without it,
postProcessing/eABAMeshMotion/<startTime>/{joints,bodies}.dat of the case
(the folders of a run and its restarts joined in time order: a restart
folder, whose first row is its first step, replaces the rows of the earlier
folders from that time on), and writes, in OUTDIR (default DIR/plots):

  trajectory.png         (a) x-z trajectory of the drone: x = q_1 (Tx),
                         z = q_0 (Tz), displacement of the surge link from
                         its start;
  forceCoefficients.png  (b) wing force coefficients in the global frame
                             C_xI = F_x/(0.5 rho S U_ref^2), C_zI likewise,
                         against t f (cycles), downstroke shaded (phi
                         decreasing, qDot_2 < 0);
  prescribedJoints.png   (c) q_2 (flapping phi) and q_3 (pitching alpha)
                         against the analytic Wang motion evaluated here
                         from the imposedMotion entries of the run's
                         constant/dynamicMeshDict, and their difference;
  stepTimers.png         (d) the step-timer bar chart
                         (flapfoam.plots.step_timers on
                         postProcessing/stepTimers).

Reference values (docs/paper.md section 3):
  S = pi/4 c_r R = R cbar (planform area of the wing);
  U_ref = 4 f A_phi R2,  R2 = sqrt(int c r^2 dr / S), the radius of
  gyration of the planform ABOUT THE FLAPPING AXIS: r is measured from the
  axis, from R0 (root) to R0 + R (tip), c = c(r - R0) of flapfoam.models.wing_geometry.
  Closed form for the semi-ellipse: R2^2 = R0^2 + 8/(3 pi) R0 R + R^2/4,
  R2 = 45.67 mm, U_ref = 4.783 m/s (r from the root instead: R2 = R/2).
  f, A_phi from the flapping entry, rho from rhoInf of the dictionary.

Times: the load in the bodies.dat row of time t_k is the one the model
used for the step to t_k, computed from the flow at the start of that step
(t_{k-1}); it is plotted at t_{k-1}.

Prints a summary (rows, time span, final position, mean coefficients over
the complete cycles, largest prescribed-joint deviation).  Exit status
non-zero if the data are missing.

Uses Debian's python (/usr/bin/python3) with numpy and matplotlib (Agg).
"""


import argparse
import math
import os
from dataclasses import dataclass

import numpy as np

from flapfoam.io import flight_data
from flapfoam.models import wing_geometry as geo
from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.plots.plotting import path, plt, save, shade_downstrokes, step_timers_chart
from flapfoam.io.tables import joined_table, start_folders
from flapfoam.models.wang import imposed_joints
from flapfoam.errors import FlapFoamError


@dataclass
class Reference:
    """The prescribed joints ({index: motion}), rho, the flapping frequency
    f, U_ref and q_ref (dynamic pressure times area)."""
    joints: dict
    rho: float
    f: float
    Uref: float
    qref: float


@dataclass
class Run:
    """A run's joints and bodies tables (J, B; column indices jc, bc), its
    times t, where they come from (source) and its Reference (ref)."""
    J: object
    B: object
    jc: dict
    bc: dict
    t: object
    source: str
    ref: Reference
    model: str = "CFD"

    @property
    def joints(self):
        return self.ref.joints

    @property
    def f(self):
        return self.ref.f

    @property
    def Uref(self):
        return self.ref.Uref

    @property
    def qref(self):
        return self.ref.qref


def reference_values(coeffs):
    """The prescribed joints, f, U_ref and the dynamic pressure times area
    of the multibody coefficients (the module's docstring)."""
    joints = imposed_joints(coeffs)
    rho = float(coeffs.get("rhoInf", ["1.2"])[0])
    # the flapping joint: the motion named flapping (the body-wing drone's
    # joint 3), else the single-wing drone's joint 2
    flap = next((m for m in joints.values() if m.name == "flapping"),
                joints.get(2))
    f = flap.frequency if flap else 20.0
    Aphi = flap.amplitude if flap else 75.0*math.pi/180.0
    Uref = 4.0*f*Aphi*geo.radius_of_gyration()
    return Reference(joints, rho, f, Uref,
                     0.5*rho*geo.planform_area()*Uref**2)


def read_run(case, dict_path):
    """The run's tables, prescribed joints and reference values; prints
    them."""
    if not os.path.isfile(dict_path):
        raise FlapFoamError("plotRun: no %s (-case: a run folder)" % dict_path)
    coeffs = multibody_coeffs(dict_path)
    ref = reference_values(coeffs)

    base = os.path.join(case, "postProcessing", "eABAMeshMotion")
    tables = flight_data.tables(case)
    if tables is not None:
        jcols, J, bcols, B = tables
        source = "flightData.h5"
        print("plotRun: reading %s" % flight_data.find(case))
    else:
        if not start_folders(base):
            raise FlapFoamError("plotRun: no %s/<time>/joints.dat and no flightData.h5"
                                % base)
        jcols, J = joined_table(base, "joints.dat",
                                keep_earlier_at_start=False)
        bcols, B = joined_table(base, "bodies.dat", keep_earlier_at_start=True)
        source = "joints.dat: 12 digits"
    jc = {c: i for i, c in enumerate(jcols)}
    bc = {c: i for i, c in enumerate(bcols)}
    t = J[:, 0]

    print("plotRun: %d steps, t = %.6g ... %.6g s (%.3f cycles), %d restart "
          "folder(s)" % (len(t) - 1, t[0], t[-1], (t[-1] - t[0])*ref.f,
                         max(len(start_folders(base)) - 1, 0)))
    print("plotRun: S = %.6g m^2, R2 = %.6g m (about the flapping axis; "
          "quadrature %.6g), U_ref = 4 f A_phi R2 = %.6g m/s, rho = %g"
          % (geo.planform_area(), geo.radius_of_gyration(),
             geo.radius_of_gyration_quadrature(), ref.Uref, ref.rho))
    attrs = flight_data.load(case)[0] if flight_data.find(case) else {}
    model = flight_data.model_label(attrs, coeffs)
    print("plotRun: model %s" % model)
    return Run(J, B, jc, bc, t, source, ref, model)


def trajectory(r, out):
    """(a) x-z trajectory of the surge link."""
    J, jc, t = r.J, r.jc, r.t
    x = J[:, jc["q_1"]]
    z = J[:, jc["q_0"]]
    fig = path(x, z, t, (
        "x = q_1 (Tx) [mm]", "z = q_0 (Tz) [mm]",
        "Single-wing drone: trajectory of the surge link (%s)" % r.model),
        lw=1.2)
    save(fig, out, "trajectory.png")
    print("plotRun: final x = %.6g m, z = %.6g m, xDot = %.6g, zDot = %.6g "
          "m/s" % (x[-1], z[-1], J[-1, jc["qDot_1"]], J[-1, jc["qDot_0"]]))


def coefficients(B, bc, qref):
    """The wing's C_xI and C_zI of the bodies table B (columns bc) at the
    times of their flow, t_{k-1} (the row of t_k holds that load)."""
    return (B[:-1, 0], B[1:, bc["wing:Fx"]]/qref, B[1:, bc["wing:Fz"]]/qref)


def force_coefficients(r, out):
    """(b) wing force coefficients: the row of t_k holds the load of the
    flow at t_{k-1}."""
    J, jc, B, bc, t = r.J, r.jc, r.B, r.bc, r.t
    f, qref, Uref = r.f, r.qref, r.Uref
    if not ("wing:Fx" in bc and len(B) > 1):
        return
    t_f, Cx, Cz = coefficients(B, bc, qref)
    # the phase of the stroke at the load times
    q_dot2 = np.interp(t_f, t, J[:, jc["qDot_2"]]) if "qDot_2" in jc \
        else np.zeros_like(t_f)
    fig, ax = plt.subplots(figsize=(8, 4.5))
    shade_downstrokes(ax, f*t_f, q_dot2)
    ax.plot(f*t_f, Cx, label="C_xI")
    ax.plot(f*t_f, Cz, label="C_zI")
    ax.axhline(0, color="k", lw=0.5)
    # The impulsive start (the flow at rest, the wing at full speed with
    # -midStroke) gives coefficients of order 1e3 for a few steps: the
    # range is clipped to median +- 10 scaled median absolute deviations
    # (at least the 2-98 percentile range) when the spikes would hide
    # the rest; the full range is printed
    both = np.concatenate([Cx, Cz])
    med = np.median(both)
    spread = 10*1.4826*np.median(np.abs(both - med)) + 1e-12
    p2, p98 = np.percentile(both, [2, 98])
    lo, hi = min(med - spread, p2), max(med + spread, p98)
    if len(both) > 40 and (both.min() < lo or both.max() > hi):
        pad = 0.05*(hi - lo)
        ax.set_ylim(lo - pad, hi + pad)
        ax.text(0.01, 0.01, "range clipped: C from %.3g to %.3g"
                % (both.min(), both.max()), transform=ax.transAxes,
                fontsize=8, va="bottom")
    print("plotRun: C_xI from %.4g to %.4g, C_zI from %.4g to %.4g"
          % (Cx.min(), Cx.max(), Cz.min(), Cz.max()))
    ax.set_xlabel("t f [cycles]")
    ax.set_ylabel("C = F / (0.5 rho S U_ref^2)")
    ax.set_title("Wing force coefficients (global frame), U_ref = %.3f "
                 "m/s" % Uref)
    ax.grid(True, alpha=0.3)
    ax.legend()
    save(fig, out, "forceCoefficients.png")
    cycle_means(r, t_f, Cx, Cz)
    print("plotRun: last C_xI = %.6g, C_zI = %.6g" % (Cx[-1], Cz[-1]))


def cycle_means(r, t_f, Cx, Cz):
    """Print, per whole cycle of the run (its end time decides: the load of
    the last step comes from the flow one step earlier), the mean C_xI and
    C_zI (weighted by the steps) and x, z at its end; then the means over
    all of them."""
    t, f, J, jc = r.t, r.f, r.J, r.jc
    n_cycles = int(math.floor((t[-1] - t[0])*f + 1e-9))
    w = np.diff(t)                  # the step each load acted over
    for k in range(1, n_cycles + 1):
        sel = (t_f >= t[0] + (k - 1)/f - 1e-12) & (t_f < t[0] + k/f - 1e-12)
        if sel.any():
            end = t[0] + k/f
            print("plotRun: cycle %d: mean C_xI = %.6g, C_zI = %.6g; at its "
                  "end x = %.6g m, z = %.6g m" % (
                      k, np.sum(w[sel]*Cx[sel])/np.sum(w[sel]),
                      np.sum(w[sel]*Cz[sel])/np.sum(w[sel]),
                      np.interp(end, t, J[:, jc["q_1"]]),
                      np.interp(end, t, J[:, jc["q_0"]])))
    if n_cycles >= 1:
        sel = t_f < t[0] + n_cycles/f - 1e-12
        print("plotRun: mean C_xI = %.6g, C_zI = %.6g over %d cycle(s)"
              % (np.sum(w[sel]*Cx[sel])/np.sum(w[sel]),
                 np.sum(w[sel]*Cz[sel])/np.sum(w[sel]), n_cycles))


def prescribed_joints(r, out):
    """(c) prescribed joints against the analytic motion."""
    J, jc, t, f, joints, source = r.J, r.jc, r.t, r.f, r.joints, r.source
    if not joints:
        return
    fig, axes = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    worst = 0.0
    for qi, ev in sorted(joints.items()):
        q, _, _ = ev(t)
        sim = J[:, jc["q_%d" % qi]]
        label = "q_%d %s" % (qi, ev.name)
        axes[0].plot(f*t, np.degrees(q), "-", lw=1,
                     label=label + " analytic")
        axes[0].plot(f*t, np.degrees(sim), ".", ms=3,
                     markevery=max(1, len(t)//200),
                     label=label + " eABAMeshMotion")
        err = np.abs(sim - q)
        worst = max(worst, err.max()/ev.amplitude)
        axes[1].semilogy(f*t, np.maximum(err, 1e-18), lw=1,
                         label="|q_%d - analytic|" % qi)
    axes[0].set_ylabel("angle [deg]")
    axes[0].grid(True, alpha=0.3)
    axes[0].legend(fontsize=7)
    axes[1].set_ylabel("|difference| [rad]")
    axes[1].set_xlabel("t f [cycles]")
    axes[1].grid(True, alpha=0.3)
    axes[1].legend(fontsize=7)
    axes[0].set_title("Prescribed joints against the Wang kinematics "
                      "(%s)" % source)
    save(fig, out, "prescribedJoints.png")
    print("plotRun: prescribed joints: max |q - analytic|/amplitude = "
          "%.3g" % worst)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1],
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("-case", default=".", help="case directory")
    ap.add_argument("-o", dest="output", default=None,
                    help="output directory (default CASE/plots; a relative "
                         "path is relative to the working directory)")
    ap.add_argument("-dict", default=None,
                    help="multibody dictionary (default "
                         "CASE/constant/dynamicMeshDict)")
    args = ap.parse_args()

    case = args.case
    out = args.output or os.path.join(case, "plots")
    r = read_run(case, args.dict or os.path.join(case, "constant",
                                                "dynamicMeshDict"))
    os.makedirs(out, exist_ok=True)         # after the run is found
    trajectory(r, out)
    force_coefficients(r, out)
    prescribed_joints(r, out)

    # (d) step timers
    rc = step_timers_chart(case, out, os.path.basename(os.path.abspath(case)))
    if rc != 0:
        print("plotRun: the step-timer chart failed (exit %d)" % rc)
        return rc
    print("plotRun: wrote %s/{trajectory,forceCoefficients,prescribedJoints,"
          "stepTimers}.png" % out)
    return 0
