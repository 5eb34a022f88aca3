# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The grid study of the single-wing drone (the paper's section 5):
one whole flapping cycle from rest on each mesh level, the case's defaults,
and per level

    C_zI, C_xI   the wing's force coefficients, cycle means;
    z, x         the drone's heave and surge after the cycle [mm];
    C_M          the wing's aerodynamic pitching moment about its pitch axis
                 (through the centre of mass, along Rz(q_2) y), over
                 q_ref c_mean: its cycle mean and its RMS.

With three levels (coarse to fine: 3, 2, 1) of representative cell sizes
h = N^(-1/3) (N the cells of both meshes), Celik et al. (2008, J. Fluids
Eng. 130, 078001): the apparent order p of each quantity (fixed-point
iteration of p = |ln|e32/e21| + q(p)|/ln r21, q = ln((r21^p - s)/(r32^p - s)),
s = sign(e32/e21)), the extrapolated value phi_ext = (r21^p phi1 - phi2)/
(r21^p - 1), the fine-grid convergence index GCI = 1.25 |phi1 - phi2|/
|phi1| / (r21^p - 1) (Roache's safety factor 1.25), and each level's error
against phi_ext.  Oscillatory convergence (s < 0) is flagged.

    flapfoam grid_study CASE ... [-out DIR] [-cycles N]

CASEs the runs, coarsest first (a run still short of its cycle is listed
with the time it reached and left out); writes DIR/table.md and
DIR/gridStudy.png when DIR is given.
"""

import argparse
from dataclasses import dataclass, field
import math
import os
import sys

import numpy as np

from flapfoam.plots.backend import pyplot
from flapfoam.io import run_series
from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.checks.pimple_guard import read_run
from flapfoam.plots.drone import reference_values
from flapfoam.models import wing_geometry as geo
from flapfoam.errors import FlapFoamError, run_tool

SAFETY = 1.25
QUANTITIES = (("C_zI", "mean C_zI"), ("C_xI", "mean C_xI"),
              ("z", "z after [mm]"), ("x", "x after [mm]"),
              ("C_M", "mean C_M"), ("C_M_rms", "RMS C_M"))
PAPER_POSITION_ERRORS = "6.1 %, 2.3 %, 1.3 % (coarse, fine, fine+)"


def cells(case):
    """The cells of the case's mesh (constant/polyMesh/owner's note, in
    its ascii header whatever the format)."""
    with open(os.path.join(case, "constant", "polyMesh", "owner"),
              "rb") as f:
        for line in f.read(4096).decode("ascii", "replace").splitlines():
            if "nCells:" in line:
                return int(line.split("nCells:")[1].split()[0])
    raise ValueError("%s: no nCells in constant/polyMesh/owner" % case)


@dataclass
class Level:
    """One level's run over its first cycle(s)."""
    case: str
    cells: int
    values: dict = field(default_factory=dict)

    @property
    def name(self):
        return os.path.basename(os.path.normpath(self.case))

    @property
    def h(self):
        return self.cells**(-1.0/3.0)


def pitching_moment(case, t0, t1):
    """The wing's pitching moment coefficient C_M(t) over [t0, t1]: the
    moment about the centre of mass along the pitch axis Rz(q_2) y, over
    q_ref c_mean (rows: the load of the flow at the previous row's time)."""
    ref = reference_values(multibody_coeffs(
        os.path.join(case, "constant", "dynamicMeshDict")))
    series = run_series.read(case)
    phi = series.q[:-1, 2]
    M = series.bodies["wing"].moment
    m = -np.sin(phi)*M[1:, 0] + np.cos(phi)*M[1:, 1]
    t = series.time[:-1]
    sel = (t >= t0) & (t <= t1)
    return t[sel], m[sel]/(ref.qref*geo.CBAR)


def read_level(case, n_cycles):
    """The level's quantities over its first n_cycles."""
    run = read_run(case, n_cycles)
    level = Level(case, cells(case))
    t, cm = pitching_moment(case, run.t0, run.t1)
    w = np.gradient(t)
    level.values = {
        "C_zI": run.mean(run.cz), "C_xI": run.mean(run.cx),
        "z": 1e3*run.at_end(run.z), "x": 1e3*run.at_end(run.x),
        "C_M": float(np.sum(w*cm)/np.sum(w)),
        "C_M_rms": float(np.sqrt(np.sum(w*cm**2)/np.sum(w))),
    }
    return level


@dataclass
class Richardson:
    """Celik's procedure for one quantity on three levels (fine first)."""
    phi: tuple          # fine, medium, coarse
    r21: float
    r32: float
    p: float = math.nan
    extrapolated: float = math.nan
    gci: float = math.nan
    oscillatory: bool = False

    def __post_init__(self):
        if not (self.r21 > 1 and self.r32 > 1):
            raise ValueError("refinement ratios %g, %g: the levels must be"
                             " given coarsest first, each finer than the"
                             " last" % (self.r32, self.r21))
        e21 = self.phi[1] - self.phi[0]
        e32 = self.phi[2] - self.phi[1]
        if e21 == 0 or e32 == 0:
            return
        s = math.copysign(1.0, e32/e21)
        self.oscillatory = s < 0
        p = abs(math.log(abs(e32/e21)))/math.log(self.r21)
        for _ in range(500):
            q = math.log((self.r21**p - s)/(self.r32**p - s))
            p_new = abs(math.log(abs(e32/e21)) + q)/math.log(self.r21)
            if abs(p_new - p) < 1e-12:
                break
            p = p_new
        self.p = p_new
        f = self.r21**self.p
        self.extrapolated = (f*self.phi[0] - self.phi[1])/(f - 1)
        self.gci = SAFETY*abs(e21/self.phi[0])/(f - 1)

    def error(self, phi):
        """|phi - phi_ext| / |phi_ext|."""
        return abs(phi - self.extrapolated)/abs(self.extrapolated)


def richardson(levels, key):
    """Richardson of the three finest levels (levels coarsest first)."""
    coarse, medium, fine = levels[-3:]
    return Richardson((fine.values[key], medium.values[key],
                       coarse.values[key]),
                      medium.h/fine.h, coarse.h/medium.h)


def table(levels):
    """Markdown: the values per level, then Richardson and GCI."""
    names = [lv.name for lv in levels]
    rows = ["| quantity | " + " | ".join(names) + " |"
            + (" p | extrapolated | GCI fine | " if len(levels) >= 3 else "")
            + (" | ".join("error %s" % n for n in names[-3:])
               + " |" if len(levels) >= 3 else ""),
            "|---|" + "---:|"*len(names)
            + ("---:|---:|---:|" + "---:|"*3 if len(levels) >= 3 else "")]
    rows.append("| cells | " + " | ".join("%d" % lv.cells for lv in levels)
                + " |" + (" | | | | | |" if len(levels) >= 3 else ""))
    for key, label in QUANTITIES:
        row = "| %s | " % label + " | ".join(
            "%.5g" % lv.values[key] for lv in levels) + " |"
        if len(levels) >= 3:
            r = richardson(levels, key)
            row += " %.2f%s | %.5g | %.2f %% | " % (
                r.p, " (osc.)" if r.oscillatory else "", r.extrapolated,
                100*r.gci)
            row += " | ".join("%.2f %%" % (100*r.error(lv.values[key]))
                              for lv in levels[-3:]) + " |"
        rows.append(row)
    return "\n".join(rows) + "\n"


def plot(levels, png):
    """Each quantity against h, with the extrapolated value."""
    plt = pyplot()
    fig, axes = plt.subplots(2, 3, figsize=(12, 7))
    h = [lv.h/levels[-1].h for lv in levels]
    for ax, (key, label) in zip(axes.flat, QUANTITIES):
        ax.plot(h, [lv.values[key] for lv in levels], "o-")
        if len(levels) >= 3:
            r = richardson(levels, key)
            if math.isfinite(r.extrapolated):
                ax.plot([0], [r.extrapolated], "k*",
                        label="extrapolated (p %.2f)" % r.p)
                ax.legend(fontsize=8)
        ax.set_xlim(left=-0.05)
        ax.set_xlabel("h / h_finest")
        ax.set_title(label)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cases", nargs="+", help="runs, coarsest first")
    parser.add_argument("-cycles", type=float, default=1)
    parser.add_argument("-out", help="folder of table.md, gridStudy.png")
    args = parser.parse_args(argv)
    levels = []
    for case in args.cases:
        name = os.path.basename(os.path.normpath(case))
        if not os.path.isfile(os.path.join(case, "constant", "polyMesh",
                                           "owner")):
            print("grid_study: level %s left out: no run with a mesh in %s"
                  % (name, case))
            continue
        try:
            levels.append(read_level(case, args.cycles))
        except (FlapFoamError, OSError, ValueError, KeyError) as short:
            print("grid_study: level %s left out: %s" % (name, short))
    if not levels:
        return 1
    text = table(levels)
    print(text)
    if len(levels) < 3:
        print("grid_study: %d level(s) complete: Richardson needs 3"
              % len(levels))
    if args.out:
        os.makedirs(args.out, exist_ok=True)
        with open(os.path.join(args.out, "table.md"), "w") as f:
            f.write(text)
        plot(levels, os.path.join(args.out, "gridStudy.png"))
    return 0


if __name__ == "__main__":
    sys.exit(run_tool(main))
