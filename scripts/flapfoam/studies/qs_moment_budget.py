# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
What a CFD run's wing moment has that the quasi-steady wing lacks: the
run's fluid load on the wing against the quasi-steady (QS) strips of its
dictionary's aerodynamics entry (coefficients and centre of pressure as
written there) at the wing's own measured motion, row by row.

    flapfoam qs_moment_budget CASE [-dict DICT] [-wing NAME]
        [-momentAbout BODY] [-skip N] [-until T] [-json FILE]

Prints, over the rows (each weighted by its time step; means over the
last whole flapping cycle of them):
  - the moment about the wing's pitch axis (the span through the root):
    the run's RMS, the QS model's R^2 (its centre of pressure is all it
    has there), and the R^2 of the fluid's added inertia and rotational
    damping about that axis, M = -I_a alpha'' - C alpha' (the pitching
    joint's acceleration and rate; I_a, C fitted), with I_a;
  - the body-pitch moment (y, about the centre of mass of -momentAbout,
    as the flight data gives it): R^2 of the QS, both cycle means, and
    the share of their difference that the QS force's error carries when
    applied at 0.7 R (the force's time history), and how much of the
    error the best chordwise centre of pressure explains (R^2);
  - the mean horizontal (x) and vertical (z) force of both.
-json FILE writes the numbers.  CASE, -dict, -wing, -momentAbout, -skip,
-until as for flapfoam qs_calibrate.  numpy and h5py.
"""

import argparse
import json

import numpy as np

from flapfoam.io import run_series
from flapfoam.models.quasi_steady import Wing
from flapfoam.studies import qs_calibrate as qc
from flapfoam.errors import run_tool


def qs_loads(wing, rows):
    """(force, body-pitch moment about the rows' moment point) of the QS
    strips at every row."""
    force = np.zeros((len(rows.time), 3))
    pitch = np.zeros(len(rows.time))
    for i in range(len(rows.time)):
        F, M = wing.force(rows.E[i], rows.origin[i], rows.v_origin[i],
                          rows.omega[i])
        force[i] = F
        pitch[i] = (M - np.cross(rows.moment_point[i], F))[1]
    return force, pitch


def added_inertia(measured, joint, weights):
    """(R^2, I_a, C) of M = -I_a alpha'' - C alpha' fitted to the pitch-axis
    moment (joint: (alpha', alpha'') of the pitching joint)."""
    A = -np.column_stack([joint[1], joint[0]])
    w = np.sqrt(weights)
    x, *_ = np.linalg.lstsq(A*w[:, None], measured*w, rcond=None)
    return qc.r_squared(measured, A @ x, weights), x[0], x[1]


def pitching_joint(series, rows):
    """(rate, acceleration) at the rows of the joint that turns the wing
    about its span: the tree's last prescribed joint (the drones' wing
    pitching joint)."""
    qi = series.prescribed[-1]
    return series.q_dot[rows.rows, qi], series.q_ddot[rows.rows, qi]


def body_pitch_cop(wing, rows, error):
    """(R^2, CoP0, CoP1): a centre of pressure fitted to the error of the
    body-pitch moment (its y moment d c x dF, about any point)."""
    basis = qc.pitch_axis_basis(wing, rows, axis=np.array([0.0, 1.0, 0.0]))
    w = np.sqrt(rows.step)
    x, *_ = np.linalg.lstsq(basis*w[:, None], error*w, rcond=None)
    return qc.r_squared(error, basis @ x, rows.step), x[0], x[1]


def budget(wing, rows, series, keep):
    """The numbers of the budget (a dict); keep: the rows of the last
    whole cycle, for the means."""
    step = rows.step
    mean = lambda v: float(np.average(v[keep], weights=step[keep]))
    axis = qc.pitch_axis_moment(wing, rows)
    axis_qs = qc.pitch_axis_basis(wing, rows) @ np.array([wing.CoP0,
                                                          wing.CoP1])
    r2_inertia, inertia, damping = added_inertia(
        axis, pitching_joint(series, rows), step)
    force, pitch = qs_loads(wing, rows)
    at_07 = rows.origin + rows.E @ (wing.root + 0.7*wing.length*wing.span)
    carried = np.cross(at_07 - rows.moment_point, rows.force - force)[:, 1]
    cfd_pitch = rows.moment[:, 1]
    r2_cop, _, _ = body_pitch_cop(wing, rows, cfd_pitch - pitch)
    return {
        "body_pitch_error_r2_best_cop": float(r2_cop),
        "pitch_axis_rms_Nm": float(np.sqrt(np.average(axis**2,
                                                      weights=step))),
        "pitch_axis_r2_qs": float(qc.r_squared(axis, axis_qs, step)),
        "pitch_axis_r2_added_inertia": float(r2_inertia),
        "added_inertia_kg_m2": float(inertia),
        "rotational_damping_N_m_s": float(damping),
        "body_pitch_r2_qs": float(qc.r_squared(cfd_pitch, pitch, step)),
        "body_pitch_mean_cfd_Nm": mean(cfd_pitch),
        "body_pitch_mean_qs_Nm": mean(pitch),
        "body_pitch_mean_force_error_at_07R_Nm": mean(carried),
        "force_x_mean_cfd_N": mean(rows.force[:, 0]),
        "force_x_mean_qs_N": mean(force[:, 0]),
        "force_z_mean_cfd_N": mean(rows.force[:, 2]),
        "force_z_mean_qs_N": mean(force[:, 2]),
    }


def print_budget(b):
    print("moment about the pitch axis: run RMS %.4g N m; the QS centre of"
          " pressure explains R^2 %.4f; added inertia and rotational"
          " damping (M = -I_a alpha'' - C alpha') R^2 %.4f, I_a %.4g kg m^2,"
          " C %.4g N m s"
          % (b["pitch_axis_rms_Nm"], b["pitch_axis_r2_qs"],
             b["pitch_axis_r2_added_inertia"], b["added_inertia_kg_m2"],
             b["rotational_damping_N_m_s"]))
    diff = b["body_pitch_mean_cfd_Nm"] - b["body_pitch_mean_qs_Nm"]
    print("body-pitch moment: QS R^2 %.4f; last-cycle mean run %.4g N m, QS"
          " %.4g N m (difference %.4g); the QS force's error at 0.7 R"
          " carries %.4g N m of it (%.0f %%); the best centre of pressure"
          " explains R^2 %.4f of the error"
          % (b["body_pitch_r2_qs"], b["body_pitch_mean_cfd_Nm"],
             b["body_pitch_mean_qs_Nm"], diff,
             b["body_pitch_mean_force_error_at_07R_Nm"],
             100*b["body_pitch_mean_force_error_at_07R_Nm"]/diff
             if diff else float("nan"), b["body_pitch_error_r2_best_cop"]))
    print("mean force: x run %.4g N, QS %.4g N; z run %.4g N, QS %.4g N"
          % (b["force_x_mean_cfd_N"], b["force_x_mean_qs_N"],
             b["force_z_mean_cfd_N"], b["force_z_mean_qs_N"]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    qc.add_run_options(parser)
    parser.add_argument("-json", help="also write the numbers here")
    args = parser.parse_args()
    wing, rows = qc.run_rows(args)
    if rows.moment is None:
        qc.fail("%s: no bodies/%s/moment: nothing to budget"
                % (rows.path, wing.entry["body"][0]))
    keep, over = qc.cycle_rows(rows, wing.coeffs)
    print("qs_moment_budget: %s, wing %s (%s), %d rows t = %g to %g s;"
          " means %s" % (rows.path, wing.name, wing.path, len(rows.time),
                         rows.time[0], rows.time[-1], over))
    b = budget(Wing(wing.entry), rows, run_series.read(args.case), keep)
    print_budget(b)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(b, fh, indent=2)


if __name__ == "__main__":
    run_tool(main)
