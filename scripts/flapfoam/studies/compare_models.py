# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The CFD run of a drone case against its quasi-steady run on the same tree
(the quasi-steady model's verification): both runs' flight data (flightData.h5).

    flapfoam compare_models CFD_CASE QS_CASE [-o DIR] [-body wing]
        [-pitchJoint J] [-md FILE]

Prints, and writes as a markdown table with -md: per whole flapping cycle
of the CFD run, the time-weighted mean C_xI and C_zI of the body in both
runs and the CFD/QS ratio of C_zI; the largest differences of x(t), z(t)
(joints q_1, q_0: surge and heave) in mm and relative to the QS run's
largest displacement; with -pitchJoint J (the body pitch, e.g. q_2 of the
body-wing drone) the joint's angle at each cycle end in both runs and the
largest difference of those.  Writes DIR/compareModels-coefficients.png (C_xI,
C_zI of both, downstrokes shaded: qDot of joint 2 < 0) and
DIR/compareModels-trajectory.png (x(t), z(t) of both).  The QS run is
interpolated to the CFD run's times.  numpy, h5py, matplotlib.
"""

import argparse
import math
import os

import numpy as np

from flapfoam.io import run_series
from flapfoam.plots.plotting import cycle_axes, plt, save, shade_downstrokes
from flapfoam.errors import FlapFoamError, run_tool


def run(case, body):
    """time, q, qDot, coefficients of body, frequency of a run."""
    try:
        s = run_series.read(case)
    except FlapFoamError as e:
        raise FlapFoamError("compare_models: %s: %s" % (case, e))
    if body not in s.bodies or s.bodies[body].coefficients is None:
        raise FlapFoamError("compare_models: %s: no coefficients/%s in its flight data (bodies: %s)"
                            % (case, body, " ".join(sorted(
                                b for b, v in s.bodies.items()
                                if v.coefficients is not None))))
    return s.time, s.q, s.q_dot, s.bodies[body].coefficients, s.attrs


def cycle_means(t, C, period):
    """[(cycle, mean C_x, mean C_z)] over the whole cycles from t[0]; the
    first row (the initial state, loads NaN) left out, rows weighted by
    their time steps."""
    out = []
    n = int(math.floor((t[-1] - t[0])/period + 1e-9))
    for k in range(n):
        sel = (t > t[0] + k*period) & (t <= t[0] + (k + 1)*period + 1e-12)
        sel &= np.isfinite(C[:, 0])
        w = np.gradient(t[sel]) if sel.sum() > 1 else np.ones(sel.sum())
        out.append((k + 1, np.sum(w*C[sel, 0])/np.sum(w),
                    np.sum(w*C[sel, 1])/np.sum(w)))
    return out


def cycle_end_angles(t, q, period, n):
    """The angle q [deg] at the ends of the first n cycles from t[0]."""
    return [math.degrees(np.interp(t[0] + k*period, t, q))
            for k in range(1, n + 1)]


def compare(cfd, qs, period, pitch_joint=None):
    """Rows of the cycle table (with the pitch joint's angles at the cycle
    ends if one is given) and the trajectory differences."""
    t_c, q_c, _, c_c, _ = cfd
    t_q, q_q, _, c_q, _ = qs
    if t_q[-1] < t_c[-1] - 1e-9:
        raise FlapFoamError("compare_models: the QS run ends at t = %g s, before the"
                            " CFD run's %g s" % (t_q[-1], t_c[-1]))
    rows = []
    within = t_q <= t_c[-1] + 1e-12
    for (k, cx, cz), (_, qx, qz) in zip(
            cycle_means(t_c, c_c, period),
            cycle_means(t_q[within], c_q[within], period)):
        rows.append([k, cx, qx, cz, qz, cz/qz])
    if pitch_joint is not None:
        for row, a, b in zip(rows, cycle_end_angles(
                t_c, q_c[:, pitch_joint], period, len(rows)),
                cycle_end_angles(t_q, q_q[:, pitch_joint], period,
                                 len(rows))):
            row += [a, b]
    diffs = {}
    for name, j in (("x", 1), ("z", 0)):
        qs_at = np.interp(t_c, t_q, q_q[:, j])
        scale = np.abs(q_q[t_q <= t_c[-1] + 1e-12, j]).max()
        diffs[name] = (np.abs(q_c[:, j] - qs_at).max(), scale)
    return rows, diffs


def table(rows, diffs, t):
    pitch = bool(rows) and len(rows[0]) > 6
    lines = ["| cycle | mean C_xI CFD | mean C_xI QS | mean C_zI CFD |"
             " mean C_zI QS | C_zI CFD/QS |"
             + (" pitch at its end CFD [deg] | QS [deg] |" if pitch else ""),
             "|---:|---:|---:|---:|---:|---:|" + ("---:|---:|" if pitch
                                                  else "")]
    for row in rows:
        lines.append("| %d | %.4f | %.4f | %.4f | %.4f | %.3f |" % tuple(
            row[:6]) + (" %.2f | %.2f |" % tuple(row[6:]) if pitch else ""))
    if not rows:
        lines.append("| (no whole cycle) | | | | | |")
    if pitch:
        lines.append("")
        lines.append("pitch at the cycle ends: largest |CFD - QS| = %.2f deg"
                     % max(abs(r[6] - r[7]) for r in rows))
    for name, (d, scale) in diffs.items():
        lines.append("")
        lines.append("%s(t), 0 to %g s: largest |CFD - QS| = %.3f mm, %.3g of"
                     " the QS run's largest |%s| (%.3f mm)"
                     % (name, t, 1e3*d, d/scale if scale > 0 else 0, name,
                        1e3*scale))
    return "\n".join(lines)


def plots(cfd, qs, period, out):
    t_c, q_c, q_dot_c, c_c, _ = cfd
    t_q, q_q, _, c_q, _ = qs
    sel = t_q <= t_c[-1] + 1e-12
    fig, ax = plt.subplots(figsize=(8, 4.5))
    shade_downstrokes(ax, t_c/period, q_dot_c[:, 2])
    for C, t, style, label in ((c_c, t_c, "-", "CFD"),
                               (c_q[sel], t_q[sel], "--", "QS")):
        ax.plot(t/period, C[:, 0], "C0" + style, label="C_xI " + label)
        ax.plot(t/period, C[:, 1], "C1" + style, label="C_zI " + label)
    cycle_axes(ax, "C = F / (0.5 rho S U_ref^2)",
              "Wing force coefficients: CFD and quasi-steady")
    ax.legend(fontsize=8)
    save(fig, out, "compareModels-coefficients.png")
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for j, name, colour in ((1, "x", "C0"), (0, "z", "C1")):
        ax.plot(t_c/period, 1e3*q_c[:, j], colour + "-", label=name + " CFD")
        ax.plot(t_q[sel]/period, 1e3*q_q[sel, j], colour + "--",
                label=name + " QS")
    cycle_axes(ax, "[mm]", "Trajectory: CFD and quasi-steady")
    ax.legend(fontsize=8)
    save(fig, out, "compareModels-trajectory.png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cfd")
    parser.add_argument("qs")
    parser.add_argument("-o", default=".", help="folder of the PNGs")
    parser.add_argument("-body", default="wing")
    parser.add_argument("-frequency", type=float, default=20.0,
                        help="flapping frequency [Hz] (default 20)")
    parser.add_argument("-pitchJoint", dest="pitch_joint", type=int,
                        help="the body's pitch joint: its angle at the"
                        " cycle ends (e.g. 2 on the body-wing drone)")
    parser.add_argument("-md", help="write the table to this file")
    a = parser.parse_args()
    if not a.frequency > 0:
        parser.error("-frequency %g: a frequency > 0 is allowed"
                     % a.frequency)
    if not os.path.isdir(a.o):
        parser.error("-o %s: not a folder" % a.o)
    cfd, qs = run(a.cfd, a.body), run(a.qs, a.body)
    rows, diffs = compare(cfd, qs, 1/a.frequency, a.pitch_joint)
    text = table(rows, diffs, cfd[0][-1])
    print(text)
    if a.md:
        with open(a.md, "w") as f:
            f.write(text + "\n")
    plots(cfd, qs, 1/a.frequency, a.o)


if __name__ == "__main__":
    run_tool(main)
