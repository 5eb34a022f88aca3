# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
A gain sweep of a drone's flight controller (src/controllers)
on the quasi-steady (QS) model: a closed-loop flight from rest at every
point of a grid of the controller's gains, and how well each holds its
set-points (flapfoam.plots.control's metrics).

    flapfoam gain_sweep -grid "height.z.Kp=-20:-2:6
        height.z.Kd=-6:0:4" [-cycles 20] [-deltaT 1e-4] [-np 2]
        [-case CASE] [-variant control] [-dir DIR] [-o PREFIX]
        [-band B1,B2,... | -band LOOP.TERM=B,...] [-settle T] [-map X,Y]
        [-keep]

Grid: NAME=LO:HI:N (N values, LO and HI included), NAME=V1,V2,... or
NAME=V (flapfoam.studies.qs_sweep's grid), NAME = LOOP.TERM.GAIN, GAIN one of Kp Ki
Kd rateSetPoint (a constant): the entry eABAMeshMotionCoeffs/controller/
loops/LOOP/terms/TERM/GAIN of the case's dictionary with the variant (the
dictionary's value, or none, elsewhere).  Linked gains, one value for
several entries: NAME+NAME2+... (a NAME after + prefixed by - takes the
value negated: the mirrored loops of two wings, e.g.
leftOffset.yaw.Kp+rightOffset.yaw.Kp, leftOffset.x.Kp+-rightOffset.x.Kp).  The case (default: the
body-wing drone) is set up once by its Allrun -model quasiSteady -variant
V -cycles 1 -deltaT DT (DIR/template, log DIR/log.template); every
point is a copy of it (DIR/pNNNNN, removed after its run unless -keep or
it fails; no step timers) run by rigidBodySimulate -bodyLoad
aerodynamics for -cycles cycles, -np runs at a time.  -deltaT: the
fixed step (default 1e-4 s, 500 steps per cycle of 20 Hz: the BW drone's
z, x and theta within 0.1 mm, 0.2 mm and 0.012 deg of the case's 1e-5 s
over 20 cycles); a row of flight data every 25 steps.

Writes PREFIX.csv: per point the gains, per controlled quantity
LOOP.TERM its settlingTime, maxAbsError, meanError, rmsError and inBand
after the settling time -settle T (default: half of the run), in SI units
(flapfoam.plots.control, with its -band: the bands, defaults position
0.01 m, orientation 0.05 rad), then inBand (every quantity within its
band after T), score (the largest maxAbsError/band), status (ok, or
failed: rigidBodySimulate's exit) and seconds.  PREFIX.png: heat-maps of
maxAbsError/band per quantity and of the score over the -map pair
(default: the first two gains of more than one value; the largest over
any other such gain), out-of-band points crossed, failed runs black; or
curves when one gain varies.  Prints the in-band ("stable") region: the
number of points within the bands, the range of every gain over them,
and the best point (the smallest score).  numpy, h5py, matplotlib.
"""

import argparse
import math
import os
import shutil
import sys
import time

import numpy as np

from flapfoam.plots import control as control_plot
from flapfoam.plots.control import ControlPlotError
from flapfoam.errors import run_tool
from flapfoam.paths import project_path
from flapfoam.studies import qs_case
from flapfoam.studies.qs_case import StudyError, foam_dictionary, linked
from flapfoam.studies.qs_sweep import (Sweep, SweepError, edges, grid_points, map_pair,
                              parse_grid, write_table)

GAINS = ("Kp", "Ki", "Kd", "rateSetPoint")


class Template:
    """The case's quasi-steady run folder of one cycle, made by its Allrun
    with the variant: the controller's terms (the allowed grid names) and
    the length of a cycle; prepare() then puts placeholder words for the
    swept gains into its dictionary, filled in per point."""

    def __init__(self, case, variant, delta_t, work_dir):
        self.folder = qs_case.set_up(case, os.path.join(work_dir, "template"),
                                     ["-variant", variant, "-deltaT",
                                      repr(delta_t)])
        _, self.terms = control_plot.controlled_terms(self.folder)
        self.bounds = {"%s.%s" % (s.label, g): (-math.inf, math.inf)
                       for s in self.terms for g in GAINS}
        self.dict = os.path.join(self.folder, "constant", "dynamicMeshDict")
        self.control_dict = os.path.join(self.folder, "system", "controlDict")
        self.period = float(foam_dictionary("-entry", "endTime", "-value",
                                           self.control_dict))
        self.names = []
        self.text = None

    def allowed(self, text):
        """The grid names allowed in -grid text: every LOOP.TERM.GAIN and
        the linked groups of them text names."""
        bounds = dict(self.bounds)
        for word in text.split():
            group = word.partition("=")[0]
            if all(n in self.bounds for n, _ in linked(group)):
                bounds[group] = (-math.inf, math.inf)
        return bounds

    def prepare(self, grid, cycles):
        """Placeholders gainSweep_<i> (gainSweepNeg_<i>: negated) for the
        grid's gains; endTime of cycles; no step timers."""
        self.names = list(grid)
        qs_case.set_placeholders(
            self.dict, self.names, lambda name: "eABAMeshMotionCoeffs/"
            "controller/loops/%s/terms/%s/%s" % tuple(name.split(".")),
            "gainSweep")
        foam_dictionary("-entry", "endTime", "-set", repr(cycles*self.period),
                       self.control_dict)
        foam_dictionary("-entry", "functions/stepTimers", "-remove",
                       self.control_dict)
        with open(self.dict) as f:
            self.text = f.read()

    def write(self, case, values):
        """The folder of one point (values: {name: value})."""
        os.makedirs(os.path.join(case, "constant"))
        shutil.copytree(os.path.join(self.folder, "system"),
                        os.path.join(case, "system"))
        text = qs_case.fill_placeholders(
            self.text, "gainSweep", [values[n] for n in self.names])
        with open(os.path.join(case, "constant", "dynamicMeshDict"),
                  "w") as f:
            f.write(text)


class GainSweep(Sweep):
    """Runs the points (qsSweep's Sweep.runAll, nProcs at a time): each a
    copy of the template run by rigidBodySimulate, measured by
    controlPlot."""

    def __init__(self, template, work_dir, bands, settle, keep=False):
        Sweep.__init__(self, template, work_dir, None, None, keep)
        self.bands = bands
        self.settle = settle

    def run(self, name, values):
        """{results} of the point values ({name: value}); status failed
        (metrics NaN) where rigidBodySimulate fails."""
        case = os.path.join(self.work_dir, name)
        shutil.rmtree(case, ignore_errors=True)
        self.model.write(case, values)
        rc, seconds = qs_case.simulate(case, "log.rigidBodySimulate")
        row = {"status": "ok" if rc == 0 else "failed (exit %d)" % rc,
               "seconds": seconds}
        run = control_plot.Run(case) if rc == 0 else None
        ratios = []
        for s in self.model.terms:
            band = self.bands[s.label]
            m = run.metrics(s.label, band, self.settle) if run else \
                dict.fromkeys(control_plot.METRICS, math.nan)
            row.update(("%s.%s" % (s.label, k), v) for k, v in m.items())
            ratios.append(m["maxAbsError"]/band)
        row["score"] = float(np.max(ratios))     # NaN if one is
        row["inBand"] = int(bool(row["score"] <= 1))
        if not self.keep and rc == 0:
            shutil.rmtree(case)
        return row


def worst_grid(rows, grid, pair, value):
    """The largest value(row) over any other varying gain, on the pair's
    grid (rows: Y, columns: X); NaN (failed) wins."""
    xs, ys = (sorted(grid[p]) for p in pair)

    def worst(x, y):
        v = [value(r) for r in rows if r[pair[0]] == x and r[pair[1]] == y]
        return math.nan if any(math.isnan(a) for a in v) else max(v)

    return xs, ys, np.array([[worst(x, y) for x in xs] for y in ys])


def plot(figure, rows, grid, pair, bands):
    """Heat-maps (or curves) of maxAbsError/band per controlled quantity
    (bands: {LOOP.TERM: band}) and of the score; out-of-band points
    crossed, failed points black; figure: (path, title)."""
    path, title = figure
    from flapfoam.plots.plotting import plt
    panels = [(label, "max |e|/band after T",
               lambda r, k=label: r[k + ".maxAbsError"]/bands[k])
              for label in bands]
    panels.append(("score", "worst max |e|/band", lambda r: r["score"]))
    fig, axes = plt.subplots(1, len(panels), figsize=(4.6*len(panels), 4),
                             squeeze=False)
    for ax, (name, label, value) in zip(axes[0], panels):
        ax.set_title(name)
        if len(pair) == 1:
            rs = sorted(rows, key=lambda r: r[pair[0]])
            ax.semilogy([r[pair[0]] for r in rs], [value(r) for r in rs],
                        "o-")
            ax.axhline(1, color="k", lw=0.8)
            ax.set_xlabel(pair[0])
            ax.set_ylabel(label)
            ax.grid(True, alpha=0.3)
            continue
        xs, ys, z = worst_grid(rows, grid, pair, value)
        ax.set_facecolor("k")
        mesh = ax.pcolormesh(edges(xs), edges(ys),
                             np.ma.masked_invalid(np.log10(z)),
                             cmap="viridis", vmin=-1, vmax=1, shading="flat")
        out = np.argwhere(~(z <= 1))
        ax.plot([xs[j] for _, j in out], [ys[i] for i, _ in out], "x",
                color="r", ms=8)
        fig.colorbar(mesh, ax=ax, label="log10 " + label)
        ax.set_xlabel(pair[0])
        ax.set_ylabel(pair[1])
    fig.suptitle(title + " (x: out of band; black: failed)")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def report(rows, grid, terms, settle):
    """The in-band region and the best point."""
    good = [r for r in rows if r["inBand"]]
    print("gain_sweep: %d of %d points within the bands after %g s%s"
          % (len(good), len(rows), settle, "" if good else
             " (no stable point in the grid)"))
    for name in grid:
        if good and len(grid[name]) > 1:
            v = sorted({r[name] for r in good})
            print("gain_sweep:   %s in [%g, %g] (%d of %d values)"
                  % (name, v[0], v[-1], len(v), len(grid[name])))
    ok = [r for r in rows if not math.isnan(r["score"])]
    if not ok:
        return
    best = min(ok, key=lambda r: r["score"])
    print("gain_sweep: best: %s: score %.3g; %s" % (
        " ".join("%s %g" % (n, best[n]) for n in grid), best["score"],
        "; ".join("%s max|e| %.3g %s rms %.3g mean %.3g settled %.3g s"
                  % (s.label, s.scale*best[s.label + ".maxAbsError"],
                     s.unit, s.scale*best[s.label + ".rmsError"],
                     s.scale*best[s.label + ".meanError"],
                     best[s.label + ".settlingTime"]) for s in terms)))


def arguments(argv):
    parser = argparse.ArgumentParser(
        prog="flapfoam gain_sweep", description=__doc__.split("\n\n")[1])
    default = project_path("cases", "bodyWingDrone")
    parser.add_argument("-grid", required=True)
    parser.add_argument("-cycles", type=int, default=20)
    parser.add_argument("-deltaT", dest="delta_t", type=float, default=1e-4)
    parser.add_argument("-np", type=int, default=2)
    parser.add_argument("-case", default=default)
    parser.add_argument("-variant", default="control")
    parser.add_argument("-dir", default="/tmp/flapFoam-gainSweep")
    parser.add_argument("-o", default="gainSweep")
    parser.add_argument("-band")
    parser.add_argument("-settle", type=float, metavar="T")
    parser.add_argument("-map")
    parser.add_argument("-keep", action="store_true")
    args = parser.parse_args(argv)
    for name, least in (("cycles", 2), ("np", 1)):
        if getattr(args, name) < least:
            parser.error("-%s %d: not allowed (an integer >= %d)"
                         % (name, getattr(args, name), least))
    if not (args.delta_t > 0 and math.isfinite(args.delta_t)):
        parser.error("-deltaT %g: not allowed (> 0)" % args.delta_t)
    return args


def main(argv=None):
    args = arguments(argv)
    try:
        os.makedirs(args.dir, exist_ok=True)
        template = Template(os.path.abspath(args.case), args.variant,
                            args.delta_t, os.path.abspath(args.dir))
        grid = parse_grid(args.grid, template.allowed(args.grid))
        pair = map_pair(grid, args.map)
        bands = control_plot.parse_bands(args.band, template.terms)
        end = args.cycles*template.period
        settle = 0.5*end if args.settle is None else args.settle
        if not 0 <= settle < end:
            raise SweepError("-settle %g: not allowed (0 <= T < the run's"
                             " %g s)" % (settle, end))
        template.prepare(grid, args.cycles)
        sweep = GainSweep(template, os.path.abspath(args.dir), bands, settle,
                          args.keep)
        start = time.time()
        rows = sweep.run_all(grid_points(grid), args.np)
        write_table(args.o + ".csv", rows, list(grid))
        print("gain_sweep: %d points (%d cycles, deltaT %g s, %d at a time)"
              " in %.1f s wall, %.2f s per run: %s.csv" % (
                  len(rows), args.cycles, args.delta_t, args.np,
                  time.time() - start,
                  np.mean([r["seconds"] for r in rows]), args.o))
        title = "%s -variant %s: %d points, %d cycles, T = %g s" % (
            os.path.basename(os.path.normpath(args.case)), args.variant,
            len(rows), args.cycles, settle)
        plot((args.o + ".png", title), rows, grid, pair, bands)
        report(rows, grid, template.terms, settle)
    except (StudyError, ControlPlotError) as e:
        sys.exit("gain_sweep: %s" % e)


if __name__ == "__main__":
    run_tool(main)
