# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The closed-loop flight of controlled drone runs (src/
controllers): the controlled quantities against their set-points, the
controller's outputs, and how well the set-points are held.

    flapfoam plot_control RUN [RUN2 ...] [-o DIR] [-settle T]
        [-band B1,B2,... | -band LOOP.TERM=B,...] [-check]
        [-summary FILE [-label L]]

RUN: a run folder with constant/dynamicMeshDict (its eABAMeshMotionCoeffs/
controller, read through foamDictionary -expand) and the flight data
postProcessing/flightData/*/flightData.h5.  The controlled quantities are
the controller's terms (loops/LOOP/terms/TERM: body, quantity, component,
setPoint), measured at every row of the flight data from the body's
position, velocity, orientation or angular velocity as the controller
measures them (orientation: x roll atan2(R_zy, R_zz), y pitch
asin(-R_zx), z yaw atan2(R_yx, R_xx), R the body-to-global matrix of
bodies/BODY/orientation); the error is the measure minus the set-point
(a number, constant V, or table ((t v) ...), linear and clamped).

Per run and controlled quantity LOOP.TERM, after the settling time -settle
T (default: half of the shortest run):
    settlingTime   the time from which |error| stays within the band (the
                   row after the last one out of it; inf if the last is)
    maxAbsError    max |error| after T
    meanError      the mean error after T (the offset)
    rmsError       the root mean square error after T
    inBand         1 if maxAbsError <= band, else 0
-band: the bands, SI units (m, m/s, rad, rad/s), in the order of the
controlled quantities (the table's) or by name; defaults: position 0.01 m,
velocity 0.1 m/s, orientation 0.05 rad, angularVelocity 1 rad/s.
Printed (mm, deg) and written (SI) to DIR/control-metrics.csv; plots
DIR/control-states.png (every controlled quantity against time, the runs
overlaid, with the set-point, the band after T) and DIR/control-outputs.png
(every loop's output, the loops named by the flight data's control
columns LOOP.output).  DIR: default RUN/plots of the first run.  -check:
a PASS/FAIL line per run and quantity, exit status 1 unless every one is
within its band after T.  -summary FILE: the first run's largest errors
after T merged into the JSON object of FILE (a results folder's
summary.json), named by what they measure: closed_loop_max_abs_dz_m (a
position's z; dx, dy), closed_loop_max_abs_pitch_deg (an orientation's y;
roll x, yaw z), closed_loop_max_abs_duz_m_per_s (a velocity's),
closed_loop_max_abs_wz_deg_per_s (an angular velocity's), each with
_L appended if -label L, and closed_loop_settle_s[_L].  numpy, h5py,
matplotlib.
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

from flapfoam.io import run_series
from flapfoam.harness.checklist import report
from flapfoam.io.foam_dict import read_foam_dict
from flapfoam.errors import FlapFoamError, run_tool

# quantity: (series of run_series.Body, display scale, display unit, SI
# unit, default band [SI])
QUANTITIES = {
    "position": ("position", 1e3, "mm", "m", 0.01),
    "velocity": ("velocity", 1.0, "m/s", "m/s", 0.1),
    "orientation": ("orientation", 180/math.pi, "deg", "rad", 0.05),
    "angularVelocity": ("angular_velocity", 180/math.pi, "deg/s", "rad/s",
                        1.0),
}

# the summary's name of a measure: quantity -> (names of x y z, unit,
# factor from SI)
SUMMARY_NAMES = {
    "position": (("dx", "dy", "dz"), "m", 1.0),
    "velocity": (("dux", "duy", "duz"), "m_per_s", 1.0),
    "orientation": (("roll", "pitch", "yaw"), "deg", 180/math.pi),
    "angularVelocity": (("wx", "wy", "wz"), "deg_per_s", 180/math.pi),
}

METRICS = ("settlingTime", "maxAbsError", "meanError", "rmsError",
           "inBand")


class ControlPlotError(Exception):
    """Bad input: the message names the file or option, the value and
    what is allowed."""


def read_coeffs(case):
    """The expanded multibody coefficients (eABAMeshMotionCoeffs, else the
    whole dictionary) of a run's constant/dynamicMeshDict."""
    path = os.path.join(case, "constant", "dynamicMeshDict")
    if not os.path.isfile(path):
        raise ControlPlotError("%s: no such file (allowed: a run folder"
                               " with constant/dynamicMeshDict)" % path)
    run = subprocess.run(["foamDictionary", "-expand", path],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True)
    if run.returncode != 0:
        raise ControlPlotError("%s: foamDictionary -expand failed: %s"
                               % (path, run.stdout[-300:]))
    with tempfile.NamedTemporaryFile("w", suffix=".dict") as f:
        f.write(run.stdout)
        f.flush()
        d = read_foam_dict(f.name)
    return d.get("eABAMeshMotionCoeffs", d)


def set_point_function(tokens, where):
    """The set-point t -> value of a Function1 entry's tokens: a number,
    constant V, zero, one or table ((t v) ...) (linear, clamped)."""
    words = [w for w in tokens if w not in "()"] \
        if isinstance(tokens, list) else []
    named = {"zero": 0.0, "one": 1.0}
    try:
        if len(tokens) == 1 and words[0] in named:
            return lambda t: np.full_like(t, named[words[0]], dtype=float)
        if len(tokens) == 1 or (words[:1] == ["constant"] and
                                len(words) == 2):
            v = float(words[-1])
            return lambda t: np.full_like(t, v, dtype=float)
        if words[:1] == ["table"] and len(words) % 2 == 1 and len(words) > 1:
            pts = np.array(words[1:], dtype=float).reshape(-1, 2)
            return lambda t: np.interp(t, pts[:, 0], pts[:, 1])
    except (ValueError, IndexError):
        pass
    tokens = " ".join(tokens) if isinstance(tokens, list) else "{...}"
    raise ControlPlotError("%s '%s': not allowed here (a number, constant"
                           " V, zero, one or table ((t v) ...))"
                           % (where, tokens))


class Term:
    """A controlled quantity: the term TERM of the loop LOOP (its label
    LOOP.TERM), what it measures and its set-point."""

    def __init__(self, loop, name, entry, where):
        self.label = "%s.%s" % (loop, name)
        self.name = name
        where = "%s/%s" % (where, name)
        try:
            self.body = entry["body"][0]
            self.quantity = entry["quantity"][0]
            self.component = "xyz".index(entry["component"][0])
            tokens = entry["setPoint"]
        except (KeyError, IndexError, ValueError, TypeError):
            raise ControlPlotError("%s: not a controller term (allowed: body,"
                                   " quantity, component x|y|z, setPoint)"
                                   % where)
        if self.quantity not in QUANTITIES:
            raise ControlPlotError("%s/quantity %s: not allowed (one of: %s)"
                                   % (where, self.quantity,
                                      " ".join(QUANTITIES)))
        self.set_point = set_point_function(tokens, where + "/setPoint")
        _, self.scale, self.unit, self.si, self.default_band = \
            QUANTITIES[self.quantity]

    def measure(self, series):
        """The measured quantity at every row of the flight data (a
        run_series.RunSeries)."""
        body = series.bodies.get(self.body)
        v = getattr(body, QUANTITIES[self.quantity][0], None)
        if v is None:
            raise ControlPlotError("%s: no dataset bodies/%s/%s in the flight"
                                   " data" % (self.label, self.body,
                                              self.quantity))
        v = np.asarray(v, dtype=float)
        if self.quantity != "orientation":
            return v[:, self.component]
        # R row-major xx xy xz yx yy yz zx zy zz; Tait-Bryan z-y'-x''
        if self.component == 0:
            return np.arctan2(v[:, 7], v[:, 8])
        if self.component == 1:
            return np.arcsin(np.clip(-v[:, 6], -1, 1))
        return np.arctan2(v[:, 3], v[:, 0])


def controlled_terms(case):
    """(controller coefficients, [Term]) of a run's dictionary."""
    coeffs = read_coeffs(case)
    where = os.path.join(case, "constant", "dynamicMeshDict") \
        + ":eABAMeshMotionCoeffs/controller"
    controller = coeffs.get("controller")
    loops = controller.get("loops") if isinstance(controller, dict) \
        else None
    if not isinstance(loops, dict) or not loops:
        raise ControlPlotError("%s: no controller loops (allowed: a run of a"
                               " controlled case, e.g. the body-wing"
                               " drone's -variant control)" % where)
    terms = []
    for loop, entry in loops.items():
        for name, term in entry.get("terms", {}).items():
            terms.append(Term(loop, name, term,
                              "%s/loops/%s/terms" % (where, loop)))
    return controller, terms


class Run:
    """A controlled run: its flight data, the errors of its controlled
    quantities and its loops' outputs."""

    def __init__(self, case):
        self.case = case
        self.name = os.path.basename(os.path.normpath(case))
        self.controller, self.terms = controlled_terms(case)
        try:
            series = run_series.read(case)
        except FlapFoamError as e:
            raise ControlPlotError("%s: cannot read its flight data: %s"
                                   % (case, e))
        if len(series.time) < 2:
            raise ControlPlotError("%s: fewer than 2 rows of flight data"
                                   % case)
        self.t = np.asarray(series.time, dtype=float)
        self.measures = {s.label: s.measure(series) for s in self.terms}
        self.errors = {s.label: self.measures[s.label] - s.set_point(self.t)
                       for s in self.terms}
        columns, control = series.other.get(
            "control", ([], np.zeros((len(self.t), 0))))
        self.control = {c: control[:, i] for i, c in enumerate(columns)}
        self.loops = [c[:-len(".output")] for c in columns
                      if c.endswith(".output")]

    def metrics(self, label, band, settle):
        """{METRICS} of the controlled quantity label after settle."""
        if not settle <= self.t[-1]:
            raise ControlPlotError("-settle %g: not allowed (before the end"
                                   " of %s, t = %g s)" % (settle, self.case,
                                                          self.t[-1]))
        return error_metrics(self.t, self.errors[label], band, settle)


def error_metrics(t, e, band, settle):
    """{METRICS} of the error e at the times t, band and settle T: the
    settling time (the row after the last one out of the band; t[0] if
    none is, inf if the last is), max |e|, mean e, rms e after T, and
    whether max |e| <= band."""
    out = np.flatnonzero(~(np.abs(e) <= band))      # NaN is out
    if len(out) == 0:
        settling = t[0]
    elif out[-1] == len(t) - 1:
        settling = math.inf
    else:
        settling = t[out[-1] + 1]
    after = e[t >= settle]
    worst = float(np.max(np.abs(after)))
    return {"settlingTime": float(settling), "maxAbsError": worst,
            "meanError": float(np.mean(after)),
            "rmsError": float(np.sqrt(np.mean(after**2))),
            "inBand": int(worst <= band and np.isfinite(worst))}


def parse_bands(text, terms):
    """{label: band} of -band (positional or LABEL=B), the defaults
    elsewhere."""
    bands = {s.label: s.default_band for s in terms}
    if not text:
        return bands
    labels = list(bands)
    words = text.split(",")
    allowed = ("B1,...,B%d (SI, in the order %s) or LABEL=B,... with LABEL"
               " one of: %s; B > 0" % (len(labels), ",".join(labels),
                                        ", ".join(labels)))
    try:
        if all("=" in w for w in words):
            pairs = [w.split("=", 1) for w in words]
            if any(k not in bands for k, _ in pairs):
                raise ValueError
            given = {k: float(v) for k, v in pairs}
        elif len(words) == len(labels):
            given = dict(zip(labels, (float(w) for w in words)))
        else:
            raise ValueError
        if not all(v > 0 and math.isfinite(v) for v in given.values()):
            raise ValueError
    except ValueError:
        raise ControlPlotError("-band %s: not allowed (%s)" % (text, allowed))
    bands.update(given)
    return bands


def metric_rows(runs, band_text, settle):
    """The rows of the metrics table: one per run and controlled
    quantity."""
    rows = []
    for r in runs:
        bands = parse_bands(band_text, r.terms)
        for s in r.terms:
            row = {"run": r.name, "quantity": s.label, "measure":
                   "%s %s %s" % (s.body, s.quantity, "xyz"[s.component]),
                   "unit": s.si, "band": bands[s.label], "settle": settle}
            row.update(r.metrics(s.label, bands[s.label], settle))
            rows.append(row)
    return rows


def print_table(rows, runs):
    """The metrics in display units (mm, deg)."""
    terms = {s.label: s for r in runs for s in r.terms}
    print("%-16s %-14s %11s %9s %11s %11s %11s %6s" % (
        "run", "quantity", "band", "settled", "max|e|", "mean e",
        "rms e", "inBand"))
    for row in rows:
        s = terms[row["quantity"]]
        print("%-16s %-14s %7.3g %-3s %7.3g s %11.4g %11.4g %11.4g %6s" % (
            row["run"], row["quantity"], s.scale*row["band"], s.unit,
            row["settlingTime"], s.scale*row["maxAbsError"],
            s.scale*row["meanError"], s.scale*row["rmsError"],
            "yes" if row["inBand"] else "NO"))


def plot_states(runs, out, bands, settle):
    """control-states.png: every controlled quantity of every run against
    time, its set-point (dashed), the band of the first run after
    settle."""
    from flapfoam.plots.plotting import plt, save
    labels = list(dict.fromkeys(s.label for r in runs for s in r.terms))
    fig, axes = plt.subplots(len(labels), 1, sharex=True, squeeze=False,
                             figsize=(9, 2.6*len(labels)))
    for ax, label in zip(axes[:, 0], labels):
        for i, r in enumerate(runs):
            for s in (s for s in r.terms if s.label == label):
                unit, c, ref = s.unit, "C%d" % (i % 10), s.set_point(r.t)
                ax.plot(r.t, s.scale*r.measures[label], color=c, lw=0.8,
                        label=r.name)
                ax.plot(r.t, s.scale*ref, "--", color=c, lw=0.8)
                if i == 0:
                    after = r.t >= settle
                    ax.fill_between(
                        r.t[after], s.scale*(ref - bands[label])[after],
                        s.scale*(ref + bands[label])[after], color="0.85",
                        lw=0, label="band")
        ax.axvline(settle, color="k", lw=0.5)
        ax.set_ylabel("%s [%s]" % (label, unit))
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="best")
    axes[-1, 0].set_xlabel("t [s]")
    axes[0, 0].set_title("controlled quantities (dashed: set-points)")
    save(fig, out, "control-states.png")


def plot_outputs(runs, out):
    """control-outputs.png: every loop's output (the flight data's
    LOOP.output columns) of every run against time."""
    from flapfoam.plots.plotting import plt, save
    loops = list(dict.fromkeys(l for r in runs for l in r.loops))
    if not loops:
        raise ControlPlotError("%s: no LOOP.output column in the flight"
                               " data's control dataset" % runs[0].case)
    fig, axes = plt.subplots(len(loops), 1, sharex=True, squeeze=False,
                             figsize=(9, 2.4*len(loops)))
    for ax, loop in zip(axes[:, 0], loops):
        for i, r in enumerate(runs):
            if loop in r.loops:
                ax.step(r.t, r.control[loop + ".output"], where="post",
                        color="C%d" % (i % 10), lw=0.8, label=r.name)
        entry = runs[0].controller["loops"].get(loop, {})
        ax.set_ylabel("%s: %s.%s" % (loop, entry.get("entry", ["?"])[0],
                                     entry.get("parameter", ["?"])[0]))
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="best")
    axes[-1, 0].set_xlabel("t [s]")
    axes[0, 0].set_title("controller outputs (values as of each update)")
    save(fig, out, "control-outputs.png")


def summary_keys(rows, run, settle, label=None):
    """The summary keys of run's rows (-summary)."""
    suffix = "_" + label if label else ""
    keys = {"closed_loop_settle_s" + suffix: settle}
    terms = {s.label: s for s in run.terms}
    for row in rows:
        if row["run"] != run.name:
            continue
        s = terms[row["quantity"]]
        names, unit, factor = SUMMARY_NAMES[s.quantity]
        keys["closed_loop_max_abs_%s_%s%s" % (names[s.component], unit,
                                              suffix)] = \
            factor*row["maxAbsError"]
    return keys


def arguments(argv):
    parser = argparse.ArgumentParser(prog="flapfoam plot_control",
                                     description=__doc__.split("\n\n")[1])
    parser.add_argument("runs", nargs="+", metavar="RUN")
    parser.add_argument("-o", metavar="DIR")
    parser.add_argument("-settle", type=float, metavar="T")
    parser.add_argument("-band")
    parser.add_argument("-check", action="store_true")
    parser.add_argument("-summary", metavar="FILE")
    parser.add_argument("-label", metavar="L")
    return parser.parse_args(argv)


def default_settle(runs):
    """Half of the shortest run."""
    return min(0.5*(r.t[0] + r.t[-1]) for r in runs)


def main(argv=None):
    args = arguments(argv)
    try:
        runs = [Run(case) for case in args.runs]
        settle = default_settle(runs) if args.settle is None else args.settle
        rows = metric_rows(runs, args.band, settle)
        out = args.o or os.path.join(args.runs[0], "plots")
        os.makedirs(out, exist_ok=True)
        from flapfoam.studies.qs_sweep import write_table
        write_table(os.path.join(out, "control-metrics.csv"), rows,
                   ["run", "quantity"])
        print_table(rows, runs)
        plot_states(runs, out, parse_bands(args.band, runs[0].terms), settle)
        plot_outputs(runs, out)
        print("plot_control: settle %g s; %s/control-{states,outputs}.png,"
              " control-metrics.csv" % (settle, out))
        if args.summary:
            from flapfoam.studies.qs_case import write_summary
            write_summary(args.summary,
                          summary_keys(rows, runs[0], settle, args.label))
            print("plot_control: wrote the first run's closed_loop keys into"
                  " %s" % args.summary)
    except ControlPlotError as e:
        sys.exit("plot_control: %s" % e)
    status = 0
    if args.check:
        for row in rows:
            status |= report(row["inBand"], "plot_control %s: %s within %.4g"
                             " %s of its set-point after %g s (max |e| %.4g,"
                             " rms %.4g, mean %.4g; settled at %.4g s)"
                             % (row["run"], row["quantity"], row["band"],
                                row["unit"], settle, row["maxAbsError"],
                                row["rmsError"], row["meanError"],
                                row["settlingTime"]))
    return status


if __name__ == "__main__":
    sys.exit(run_tool(main))
