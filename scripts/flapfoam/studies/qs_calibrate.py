# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Calibrates the quasi-steady wing (bodyLoad aerodynamics, type quasiSteady)
on a CFD run, as Lee et al. (2016) did on Fluent runs: the coefficients
CL, CD0, CD1 fitted to the run's fluid force on the wing by linear least
squares.

    flapfoam qs_calibrate CASE [-dict DICT] [-wing NAME] [-momentAbout BODY]
        [-skip N] [-until T] [-components xz|xyz] [-out FILE]

The blade-element force is linear in the coefficients: per strip
    dF = 0.5 rho |u_perp|^2 c dr (CL sin 2a e_L + (CD0 + CD1 (1 - cos 2a)) e_D)
so each row of the run's flight data (postProcessing/flightData/<start>/
flightData.h5: bodies/<body>/orientation, position, velocity,
angularVelocity of the wing's body, and its fluid force) gives three basis
forces, those of (CL, CD0, CD1) = (1, 0, 0), (0, 1, 0), (0, 0, 1), from
the strips' velocities v_k = v_origin + omega x arm (v_origin, that of the
body frame's origin, from the centre of mass's velocity and the angular
velocity; the centre of mass from the dictionary's body).  The measured
force components (x and z, or all three) of every row are fitted by one
least-squares problem, each row weighted by its time step (the run's
steps may vary).

Then the chordwise centre of pressure: each strip's force acts at d =
(CoP0 + CoP1 2 alpha/pi) c from the pitch axis along the chord, so the
model's moment about the pitch axis (along the span) is linear in CoP0,
CoP1 given the fitted force; they are fitted to the run's fluid moment
about the pitch axis (the flight data's moment of the wing, taken about
the centre of mass of the body -momentAbout names, default: the
flightData function object's momentAbout of the wing in CASE/system/
controlDict, else the wing), each row weighted by its time step.

DICT (default CASE/constant/dynamicMeshDict) holds the aerodynamics entry
(NAME: default its only entry); -skip N leaves out the first N steps (the
start-up transient; the first row, the initial state whose loads are not
computed, is always left out), -until T the steps after t = T (a fit on the
first cycles of a longer run, whose later cycles it then predicts).  Prints the fit (coefficients, R^2 and the RMS
residual relative to the force's range per component, the condition
number), the mean vertical force of the CFD, of the fitted QS and of the
QS with Wang's defaults (over the whole flapping cycles of the fitted rows,
or over all of them when they cover less than a cycle), and the entry to
paste (the dictionary's entry with the fitted CL, CD0, CD1, CoP0, CoP1;
-out FILE also writes it there).  numpy and h5py.
"""

import argparse
import copy
import math
import os
import re
from dataclasses import dataclass

import numpy as np

from flapfoam.io import run_series
from flapfoam.io.flight_data import find
from flapfoam.io.foam_dict import multibody_coeffs, read_foam_dict
from flapfoam.models.quasi_steady import Wing, vec
from flapfoam.errors import FlapFoamError, run_tool

COEFFS = ("CL", "CD0", "CD1")
COP = ("CoP0", "CoP1")


def fail(message):
    raise FlapFoamError("qs_calibrate: " + message)


def wing_entry(path, name):
    """(name, entry, multibody coefficients) of the dictionary's
    aerodynamics entry NAME (None: its only one)."""
    if not os.path.isfile(path):
        fail("no dictionary %s (give -dict DICT: a dynamicMeshDict with an"
             " aerodynamics entry)" % path)
    coeffs = multibody_coeffs(path)
    aero = coeffs.get("aerodynamics")
    entries = {k: v for k, v in aero.items() if isinstance(v, dict)} \
        if isinstance(aero, dict) else {}
    if not entries:
        fail("%s: no aerodynamics entry with a wing (e.g. the drone cases'"
             " constant/dynamicMeshDict.eABA has one: -dict)" % path)
    if name is None and len(entries) > 1:
        fail("%s: aerodynamics has %d wings (%s): choose one with -wing"
             % (path, len(entries), ", ".join(entries)))
    name = name or next(iter(entries))
    if name not in entries:
        fail("%s: -wing %s: no such aerodynamics entry (allowed: %s)"
             % (path, name, ", ".join(entries)))
    return name, entries[name], coeffs


class FlightRows:
    """The rows of a run's flight data used in the fit: the wing body's
    motion (body frame origin) and the fluid force on it."""

    KEYS = {"orientation": "orientation", "position": "position",
            "velocity": "velocity", "angularVelocity": "angular_velocity",
            "force": "force"}

    def __init__(self, case, body, centre_of_mass, window):
        path = find(case)
        if path is None:
            fail("no postProcessing/flightData/*/flightData.h5 in %s (a CFD"
                 " run's flight data)" % case)
        self.path = path
        t, d = self.read(case, body)
        self.select(t, d, window)
        self.moment, self.moment_point = None, None
        if d["moment"] is not None and d["momentPoint"] is not None:
            self.moment = d["moment"][self.rows]
            self.moment_point = d["momentPoint"][self.rows]
        E = d["orientation"][self.rows].reshape(-1, 3, 3)
        arm = E @ centre_of_mass
        self.E, self.omega = E, d["angularVelocity"][self.rows]
        self.origin = d["position"][self.rows] - arm
        self.v_origin = d["velocity"][self.rows] \
            - np.cross(self.omega, arm)
        self.force = d["force"][self.rows]
        self.time = t[self.rows]
        self.step = t[self.rows] - t[self.rows - 1]

    def read(self, case, body):
        """(time, {key: rows}) of the body's series."""
        try:
            series = run_series.read(case)
        except FlapFoamError as e:
            fail(str(e))
        b = series.bodies.get(body[0], run_series.Body())
        d = {k: getattr(b, f) for k, f in self.KEYS.items()}
        missing = ["bodies/%s/%s" % (body[0], k) for k, v in d.items()
                   if v is None]
        if missing:
            fail("%s: no %s (the motion and fluid force of body %s);"
                 " its bodies: %s"
                 % (self.path, ", ".join(missing), body[0],
                    ", ".join(series.bodies) or "none"))
        d["moment"] = b.moment
        d["momentPoint"] = series.bodies.get(body[1],
                                             run_series.Body()).position
        return series.time, d

    def select(self, t, d, window):
        """self.rows: the rows after the initial state and -skip steps, up
        to t = -until (window: (skip, until or None)); every value
        finite."""
        skip, until = window
        n = len(t) - 1
        if skip < 0 or skip > n - 3:
            fail("%s: -skip %d: allowed 0 to %d (the file has %d steps"
                 " after its initial state, t = %g to %g s; the fit needs"
                 " at least 3)" % (self.path, skip, max(n - 3, 0), n,
                                   t[0], t[-1]))
        self.rows = np.arange(1 + skip, len(t))
        if until is not None:
            self.rows = self.rows[t[self.rows] <= until*(1 + 1e-12)]
            if len(self.rows) < 3:
                fail("%s: -until %g: %d steps from the start (t = %g) to it;"
                     " the fit needs at least 3: a later -until (the file"
                     " ends at t = %g)" % (self.path, until, len(self.rows),
                                          t[0], t[-1]))
        finite = np.all([np.isfinite(d[k][self.rows]).reshape(
            len(self.rows), -1).all(axis=1) for k in self.KEYS], axis=0)
        bad = np.flatnonzero(~finite)
        if len(bad):
            fail("%s: %d rows with NaN/inf motion or force from t = %g s"
                 " (allowed: only the initial state)"
                 % (self.path, len(bad), t[self.rows[bad[0]]]))


def basis_forces(wing, rows):
    """(rows, 3 coefficients, 3 components): the wing's force per unit
    CL, CD0, CD1 at every row."""
    unit = copy.copy(wing)
    basis = np.empty((len(rows.time), 3, 3))
    for j, coefficient in enumerate(COEFFS):
        for k in COEFFS:
            setattr(unit, k, 1.0 if k == coefficient else 0.0)
        for i in range(len(rows.time)):
            basis[i, j], _ = unit.force(rows.E[i], rows.origin[i],
                                        rows.v_origin[i], rows.omega[i])
    return basis


def fit(basis, rows, components):
    """(coefficients, condition number): least squares over the rows (each
    weighted by its time step) and the components (indices)."""
    w = np.sqrt(rows.step)[:, None]
    A = (basis[:, :, components]*w[:, :, None]).transpose(0, 2, 1) \
        .reshape(-1, 3)
    b = (rows.force[:, components]*w).reshape(-1)
    scale = np.linalg.norm(A, axis=0)
    if np.any(scale == 0):
        fail("the wing's motion gives no %s force in the fitted rows:"
             " nothing to fit (a wing at rest?)"
             % "/".join(c for c, s in zip(COEFFS, scale) if s == 0))
    x, _, rank, sv = np.linalg.lstsq(A/scale, b, rcond=None)
    if rank < 3:
        fail("CL, CD0, CD1 cannot be told apart over the fitted rows (rank"
             " %d of 3): fit over more of a cycle (-skip, a longer run)"
             % rank)
    return x/scale, sv[0]/sv[-1]


def pitch_axis_basis(wing, rows, axis=None):
    """(rows, 2): the model's moment per unit CoP0 and CoP1 (the force's
    shift d c^ along the chord, about any point) at every row, about the
    wing's span direction, or about a global axis (wing: the fitted
    force)."""
    basis = np.zeros((len(rows.time), 2))
    for i in range(len(rows.time)):
        st = wing.strips(rows.E[i], rows.v_origin[i], rows.omega[i])
        m = (np.cross(st["c"], st["d_f"]) @ (st["s"] if axis is None
                                              else axis)) \
            * wing.chords[st["live"]]
        basis[i] = m.sum(), (m*2*st["alpha"]/math.pi).sum()
    return basis


def pitch_axis_moment(wing, rows):
    """The run's fluid moment on the wing about its pitch axis (the span
    through the root point) at every row."""
    span = rows.E @ wing.span
    axis_point = rows.origin + rows.E @ wing.root
    moment = rows.moment + np.cross(rows.moment_point - axis_point,
                                    rows.force)
    return np.einsum("ij,ij->i", moment, span)


def fit_centre_of_pressure(wing, rows):
    """(CoP0, CoP1), the model's pitch-axis moment with them and the run's:
    least squares over the rows, each weighted by its time step."""
    basis = pitch_axis_basis(wing, rows)
    measured = pitch_axis_moment(wing, rows)
    w = np.sqrt(rows.step)
    x, _, rank, _ = np.linalg.lstsq(basis*w[:, None], measured*w,
                                    rcond=None)
    if rank < 2:
        fail("CoP0 and CoP1 cannot be told apart over the fitted rows (rank"
             " %d of 2): fit over more of a cycle" % rank)
    return x, basis @ x, measured


def r_squared(measured, model, weights):
    """R^2 of model against measured, means weighted."""
    res = np.average((measured - model)**2, weights=weights)
    spread = np.average((measured - np.average(measured, weights=weights))
                        ** 2, weights=weights)
    return 1 - res/spread if spread > 0 else np.nan


def quality(model, rows, components):
    """Per component: (R^2, RMS residual / range of the force), means
    weighted by the time steps."""
    out = []
    for c in components:
        F = rows.force[:, c]
        res = np.average((F - model[:, c])**2, weights=rows.step)
        spread = np.average((F - np.average(F, weights=rows.step))**2,
                            weights=rows.step)
        span = np.ptp(F)
        out.append((1 - res/spread if spread > 0 else np.nan,
                    np.sqrt(res)/span if span > 0 else np.nan))
    return out


def cycle_rows(rows, coeffs):
    """(rows of the whole flapping cycles at the end of the fitted ones,
    text): all of them when they cover less than one cycle (or no
    frequency)."""
    f = [float(e["frequency"][0])
         for e in coeffs.get("imposedMotion", {}).values()
         if isinstance(e, dict) and "frequency" in e]
    span = rows.time[-1] - rows.time[0] + rows.step[0]
    if not f:
        return slice(None), "over the fitted rows (no imposedMotion" \
            " frequency)"
    period = 1/min(f)
    cycles = int(np.floor(span/period + 1e-9))
    if cycles < 1:
        return slice(None), ("over the fitted rows, %.3g of a cycle of %g s:"
                             " not a cycle mean" % (span/period, period))
    keep = rows.time - rows.step >= rows.time[-1] - (cycles + 1e-9)*period
    return keep, "over the last %d whole cycle(s) of %g s" % (cycles, period)


def entry_text(name, entry, values):
    """The aerodynamics entry NAME with the fitted coefficients (values:
    {key: value})."""
    lines = ["    %s" % name, "    {"]
    keys = list(entry) + [k for k in values if k not in entry]
    for key in keys:
        if key in values:
            text = "%.8g" % values[key]
        else:
            text = re.sub(r"\(\s+", "(", " ".join(entry[key]))
            text = re.sub(r"\s+\)", ")", text)
        lines.append("        %-11s %s;" % (key, text))
    lines.append("    }")
    return "\n".join(lines)


def moment_about(case, body):
    """The body about whose centre of mass the run's flight data takes the
    moment of body (the flightData function object's coefficients entry
    in CASE/system/controlDict), body itself without one."""
    path = os.path.join(case, "system", "controlDict")
    if not os.path.isfile(path):
        return body
    for fo in read_foam_dict(path).get("functions", {}).values():
        if isinstance(fo, dict) and fo.get("type") == ["flightData"]:
            entry = fo.get("coefficients", {}).get(body, {})
            return entry.get("momentAbout", [body])[0]
    return body


@dataclass
class WingEntry:
    """The aerodynamics entry fitted: its dictionary file, name, keys and
    the multibody coefficients around it."""
    path: str
    name: str
    entry: dict
    coeffs: dict


def centre_of_pressure(defaults, fitted, rows):
    """Fit CoP0, CoP1 (the wing with the fitted force coefficients) to the
    run's moment about the pitch axis; print how much of it they explain;
    return them."""
    wing = copy.copy(defaults)
    wing.CL, wing.CD0, wing.CD1 = fitted
    cop, model, measured = fit_centre_of_pressure(wing, rows)
    print("centre of pressure: CoP0 %.8g CoP1 %.8g chords from the pitch"
          " axis (d = (CoP0 + CoP1 2 alpha/pi) c along the chord); the"
          " run's moment about the pitch axis: RMS %.4g N m, R^2 %.6f with"
          " it, %.6f on the axis (CoP 0 0)"
          % (cop[0], cop[1], np.sqrt(np.average(measured**2,
                                                weights=rows.step)),
             r_squared(measured, model, rows.step),
             r_squared(measured, 0*model, rows.step)))
    return cop


def report(wing, rows, axes):
    """Fit the wing (a WingEntry) on the rows' force components axes ("xz"
    or "xyz"), print the report and the entry; returns the entry's
    text."""
    entry, coeffs = wing.entry, wing.coeffs
    components = ["xyz".index(c) for c in axes]
    basis = basis_forces(Wing(entry), rows)
    fitted, cond = fit(basis, rows, components)
    defaults = Wing({k: v for k, v in entry.items()
                     if k not in COEFFS + COP})
    wang = np.array([defaults.CL, defaults.CD0, defaults.CD1])
    keep, over = cycle_rows(rows, coeffs)

    def mean_z(F):
        return np.average(F[keep, 2], weights=rows.step[keep])

    print("qs_calibrate: %s, body %s, %d rows t = %g to %g s, components %s"
          % (rows.path, entry["body"][0], len(rows.time),
             rows.time[0], rows.time[-1], " ".join(axes)))
    print("fitted: CL %.8g CD0 %.8g CD1 %.8g (condition number %.3g)"
          % (tuple(fitted) + (cond,)))
    negative = [k for k, x in zip(COEFFS, fitted) if x < 0]
    if negative:
        print("note: %s < 0: not a flat plate's coefficients; the rows are"
              " likely dominated by what the QS model lacks (added mass,"
              " rotational forces, the start-up): fit over whole cycles"
              % ", ".join(negative))
    print("mean F_z %s: run %.6g N" % (over, mean_z(rows.force)))
    for label, x in (("fitted", fitted), ("Wang's defaults", wang)):
        model = np.einsum("j,ijk->ik", x, basis)
        fit_text = "; ".join("%s: R^2 %.6f, RMS residual %.3g of the range"
                            % (axes[i], r2, rms) for i, (r2, rms)
                            in enumerate(quality(model, rows, components)))
        print("QS %s (CL %.4g CD0 %.4g CD1 %.4g): %s; mean F_z %.6g N ="
              " %.4f of the run's" % (label, *x, fit_text, mean_z(model),
                                       mean_z(model)/mean_z(rows.force)))
    values = dict(zip(COEFFS, fitted))
    if rows.moment is None:
        print("centre of pressure: not fitted (the flight data has no"
              " moment of the wing)")
    else:
        values.update(zip(COP, centre_of_pressure(defaults, fitted, rows)))
    text = entry_text(wing.name, entry, values)
    print("The entry to paste (aerodynamics of %s):\n%s" % (wing.path, text))
    return text


def add_run_options(parser):
    """The options of a CFD run's wing rows (qs_calibrate's and
    qs_moment_budget's): CASE, -dict, -wing, -momentAbout, -skip,
    -until."""
    parser.add_argument("case", help="a CFD run with flight data")
    parser.add_argument("-dict", help="dynamicMeshDict with the aerodynamics"
                        " entry (default CASE/constant/dynamicMeshDict)")
    parser.add_argument("-wing", help="the aerodynamics entry (default: its"
                        " only one)")
    parser.add_argument("-momentAbout", dest="moment_about", metavar="BODY",
                        help="the body about whose centre of mass the flight"
                        " data's wing moment is taken (default: the"
                        " flightData momentAbout of CASE/system/controlDict,"
                        " else the wing's body)")
    parser.add_argument("-skip", type=int, default=0,
                        help="steps left out at the start (default 0)")
    parser.add_argument("-until", type=float,
                        help="leave out the steps after this time [s] (e.g."
                        " 0.1: the first two cycles at 20 Hz)")


def run_rows(args):
    """(WingEntry, FlightRows) of the options of add_run_options."""
    path = args.dict or os.path.join(args.case, "constant",
                                     "dynamicMeshDict")
    name, entry, coeffs = wing_entry(path, args.wing)
    body = entry.get("body", ["?"])[0]
    if body not in coeffs.get("bodies", {}):
        fail("%s: aerodynamics/%s: body %s is not a body of the tree"
             " (allowed: %s)" % (path, name, body,
                                 ", ".join(coeffs.get("bodies", {}))))
    centre = vec(coeffs["bodies"][body].get("centreOfMass", ["0", "0", "0"]))
    about = args.moment_about or moment_about(args.case, body)
    if about not in coeffs.get("bodies", {}):
        fail("-momentAbout %s: not a body of the tree (allowed: %s)"
             % (about, ", ".join(coeffs.get("bodies", {}))))
    rows = FlightRows(args.case, (body, about), centre,
                      (args.skip, args.until))
    return WingEntry(path, name, entry, coeffs), rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_run_options(parser)
    parser.add_argument("-components", choices=("xz", "xyz"), default="xz",
                        help="the force components fitted (default xz)")
    parser.add_argument("-out", help="also write the entry to this file")
    args = parser.parse_args()
    wing, rows = run_rows(args)
    text = report(wing, rows, args.components)
    if args.out:
        try:
            with open(args.out, "w") as f:
                f.write(text + "\n")
        except OSError as e:
            fail("-out %s: cannot write: %s" % (args.out, e))


if __name__ == "__main__":
    run_tool(main)
