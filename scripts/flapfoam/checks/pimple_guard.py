# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The accuracy guard of the PIMPLE study (bench/pimple): a drone run (the
single-wing or the body-wing drone: its wing's loads, x = q_1, z = q_0)
against a reference run on the same mesh (the paper's settings: PISO,
4 correctors, max Co 1, p to 1e-7), over the first whole flapping cycle(s)
both runs completed.

    flapfoam pimple_guard REF CASE [-cycles N]

Per run (its flight data, log.overPimpleDyMFoam, stepTimers.dat):
  - C_xI, C_zI: the wing's force coefficients (plotSingleWing), their mean
    over the cycles (weighted by the step);
  - x = q_1, z = q_0 after the cycles (interpolated to the end time);
  - the continuity error of the cycles: the sum over the steps of the last
    "sum local" of each step (per step it is deltaT times the mean |div U|,
    so the sum does not favour fewer, longer steps);
  - steps, wall seconds (the stepTimers "total" of every step) and CPU
    seconds (ExecutionTime) of the cycles, pressure iterations per step.

The guard, a PASS/FAIL line each:
  - cycle-mean C_xI and C_zI within 1 % of the reference's (relative to
    the larger of the two means' magnitudes: C_xI's mean is near zero);
  - max |C_zI(t) - C_zI,ref(t)|, both averaged over 1 % of the cycle
    (the run interpolated to the reference's times), within 3 % of the
    reference's C_zI range over the cycles; the same step by step is
    printed (INFO), not judged: the overset's single-step spikes of C_zI
    alone exceed it (series_check);
  - x and z after the cycles within 1 % of the reference's excursion over
    them (max - min);
  - the continuity error no larger than the reference's.
Exit status 1 if any judged check fails.
"""

import argparse
import dataclasses
import math
import os
import sys

import numpy as np

from flapfoam.io import run_series
from flapfoam.io import solver_log
from flapfoam.io import step_timers
from flapfoam.harness.checklist import report
from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.plots.drone import reference_values, wing_coefficients
from flapfoam.errors import FlapFoamError, run_tool

# The guard's margins
MEAN_TOL = 0.01         # cycle means, of the larger mean magnitude
SERIES_TOL = 0.03       # instantaneous C_zI, of its range
POSITION_TOL = 0.01     # x, z after the cycles, of the excursion
SERIES_WINDOW = 0.01    # the smoothed C_zI: averaged over this of a cycle


@dataclasses.dataclass
class Cycles:
    """What one run did over the guarded cycles."""
    case: str
    t: np.ndarray           # load times [s]
    cx: np.ndarray
    cz: np.ndarray
    x: np.ndarray           # surge, heave at the joint rows' times
    z: np.ndarray
    tq: np.ndarray
    t0: float
    t1: float               # end of the guarded cycles
    steps: int = 0
    wall: float = 0.0
    cpu: float = math.nan
    continuity: float = 0.0
    p_iterations: float = math.nan

    def mean(self, c):
        """The step-weighted mean of a coefficient over [t0, t1]."""
        sel = (self.t >= self.t0) & (self.t <= self.t1)
        w = np.gradient(self.t[sel]) if sel.sum() > 1 else np.ones(1)
        return float(np.sum(w*c[sel])/np.sum(w))

    def at_end(self, q):
        return float(np.interp(self.t1, self.tq, q))


def read_run(case, n_cycles):
    """The run's Cycles over its first n_cycles cycles."""
    ref = reference_values(multibody_coeffs(
        os.path.join(case, "constant", "dynamicMeshDict")))
    series = run_series.read(case)
    t, cx, cz = wing_coefficients(series, ref.qref)
    tq = series.time
    t0 = tq[0]
    run = Cycles(case=case, t=t, cx=cx, cz=cz, x=series.q[:, 1],
                 z=series.q[:, 0], tq=tq, t0=t0, t1=t0 + n_cycles/ref.f)
    # A run of part of a cycle ends within its last step of the end
    if len(tq) > 1 and tq[-1] < run.t1 <= 2*tq[-1] - tq[-2]:
        run.t1 = tq[-1]
    if tq[-1] < run.t1*(1 - 1e-9):
        raise FlapFoamError("pimple_guard: %s reached t = %g s, not the end of %g "
                            "cycle(s), %g s" % (case, tq[-1], n_cycles, run.t1))
    steps = solver_log.steps(case)
    sel = (steps[:, 0] > t0) & (steps[:, 0] <= run.t1*(1 + 1e-9))
    run.steps = int(sel.sum())
    run.continuity = float(np.nansum(steps[sel, 1]))
    run.p_iterations = float(steps[sel, 2].mean()) if run.steps else math.nan
    run.cpu = float(steps[sel, 3].sum())
    columns, data = step_timers.read_input(
        os.path.join(case, "postProcessing", "stepTimers"), 0)
    tcol, total = data[:, columns.index("time")], \
        data[:, columns.index("total")]
    run.wall = float(total[(tcol > t0) & (tcol <= run.t1*(1 + 1e-9))].sum())
    return run


@dataclasses.dataclass
class Check:
    """One line of the guard: its name, the measured share of the allowed
    (at most 1 passes), the text, and whether it counts for the verdict
    (the step-by-step C_zI does not: informative)."""
    name: str
    ratio: float
    text: str
    counts: bool = True

    @property
    def ok(self):
        return self.ratio <= 1.0


def mean_checks(ref, run):
    """The cycle means of C_xI and C_zI."""
    scale = max(abs(ref.mean(ref.cx)), abs(ref.mean(ref.cz)))
    out = []
    for name in ("cx", "cz"):
        a, b = ref.mean(getattr(ref, name)), run.mean(getattr(run, name))
        out.append(Check(
            "C_%sI" % name[1], abs(b - a)/(MEAN_TOL*scale),
            "cycle-mean C_%sI %.5g against %.5g: difference %.3g %% of %.4g "
            "(at most %g %%)" % (name[1], b, a, 100*abs(b - a)/scale, scale,
                                 100*MEAN_TOL)))
    return out


def series_check(ref, run):
    """The largest instantaneous difference of C_zI: informative, not in
    the verdict.  The overset makes single-step spikes of C_zI (hole
    cutting, donor changes) up to about a quarter of its range (SW tiny,
    the paper's settings, against its own average over 1 % of the cycle),
    at times that move when the steps do: a run at max Co 0.8, more
    accurate than the reference, is 15 % of the range from it step by
    step and 0.26 % smoothed (bench/pimple/results.md)."""
    sel = (ref.t >= ref.t0) & (ref.t <= ref.t1)
    span = np.ptp(ref.cz[sel])
    diff = np.abs(np.interp(ref.t[sel], run.t, run.cz) - ref.cz[sel])
    noise = np.abs(ref.cz[sel] - smoothed(
        ref.t, ref.cz, ref.t[sel], SERIES_WINDOW*(ref.t1 - ref.t0)))
    return Check(
        "C_zI(t)", diff.max()/(SERIES_TOL*span),
        "largest |C_zI - reference| %.4g at t = %.6g s: %.3g %% of the range "
        "%.4g (%g %%: informative, the reference's own spikes reach %.3g %% "
        "of the range)" % (diff.max(), ref.t[sel][np.argmax(diff)],
                           100*diff.max()/span, span, 100*SERIES_TOL,
                           100*noise.max()/span), counts=False)


def smoothed(t, c, at, window):
    """The time average of c(t) (piecewise linear) over [x - window/2,
    x + window/2] for each x of at (clipped to the data)."""
    area = np.concatenate([[0.0], np.cumsum(0.5*(c[1:] + c[:-1])
                                            * np.diff(t))])
    lo = np.clip(at - 0.5*window, t[0], t[-1])
    hi = np.clip(at + 0.5*window, t[0], t[-1])
    return (np.interp(hi, t, area) - np.interp(lo, t, area)) \
        / np.maximum(hi - lo, 1e-300)


def smoothed_series_check(ref, run):
    """The largest difference of C_zI averaged over SERIES_WINDOW of the
    cycle: the waveform without the single-step spikes of the overset
    (hole cutting, donor changes), which fall at other times when the
    steps differ."""
    sel = (ref.t >= ref.t0) & (ref.t <= ref.t1)
    window = SERIES_WINDOW*(ref.t1 - ref.t0)
    a = smoothed(ref.t, ref.cz, ref.t[sel], window)
    b = smoothed(run.t, run.cz, ref.t[sel], window)
    span = np.ptp(ref.cz[sel])
    diff = np.abs(b - a)
    return Check(
        "C_zI(t) smoothed", diff.max()/(SERIES_TOL*span),
        "largest |C_zI - reference|, both averaged over %g %% of the cycle, "
        "%.4g at t = %.6g s: %.3g %% of the range %.4g (at most %g %%)"
        % (100*SERIES_WINDOW, diff.max(), ref.t[sel][np.argmax(diff)],
           100*diff.max()/span, span, 100*SERIES_TOL))


def position_checks(ref, run):
    """x and z after the cycles."""
    inside = (ref.tq >= ref.t0) & (ref.tq <= ref.t1)
    out = []
    for name in ("x", "z"):
        q_ref, q = getattr(ref, name), getattr(run, name)
        excursion = max(np.ptp(q_ref[inside]), 1e-300)
        d = abs(run.at_end(q) - ref.at_end(q_ref))
        out.append(Check(
            name, d/(POSITION_TOL*excursion),
            "%s after the cycles %.6g m against %.6g m: %.3g %% of the "
            "excursion %.4g m (at most %g %%)"
            % (name, run.at_end(q), ref.at_end(q_ref), 100*d/excursion,
               excursion, 100*POSITION_TOL)))
    return out


def guard(ref, run):
    """The guard's checks of run against ref."""
    return mean_checks(ref, run) + [series_check(ref, run),
                                    smoothed_series_check(ref, run)] \
        + position_checks(ref, run) + [Check(
            "continuity", run.continuity/max(ref.continuity, 1e-300),
            "continuity error of the cycles %.4g against %.4g (no larger)"
            % (run.continuity, ref.continuity))]


def describe(run):
    """One line: steps, cost and iterations."""
    return ("%s: %d steps, wall %.1f s, CPU %.1f s, %.1f p iterations a "
            "step, C_xI %.5g, C_zI %.5g, x %.5g m, z %.5g m"
            % (run.case, run.steps, run.wall, run.cpu, run.p_iterations,
               run.mean(run.cx), run.mean(run.cz), run.at_end(run.x),
               run.at_end(run.z)))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("ref", help="the reference run (paper settings)")
    ap.add_argument("case", help="the run to check")
    ap.add_argument("-cycles", type=float, default=1,
                    help="whole cycles from the start (default 1)")
    args = ap.parse_args(argv)
    ref = read_run(args.ref, args.cycles)
    run = read_run(args.case, args.cycles)
    print(describe(ref))
    print(describe(run))
    print("cost: wall %.3gx, CPU %.3gx, steps %.3gx of the reference"
          % (ref.wall/run.wall, ref.cpu/run.cpu, ref.steps/run.steps))
    rc = 0
    for check in guard(ref, run):
        if check.counts:
            rc |= report(check.ok, check.text)
        else:
            print("INFO %s" % check.text)
    return rc


if __name__ == "__main__":
    sys.exit(run_tool(main))
