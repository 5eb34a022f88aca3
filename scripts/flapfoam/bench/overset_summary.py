# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Table and chart of the overset stencil benchmark (bench/overset/run).

    flapfoam overset_summary -dir DIR [-startup K] [-o PREFIX] RUN [RUN ...]

Each RUN is DIR/<level>-np<N>-<stencil>[-r<round>], a case run by
cases/singleWingDrone/Allrun, with DIR/<RUN>.memory from flapfoam.bench.peak_memory.
Writes PREFIX.md (markdown table, one row per level, ranks and stencil:
median per step after K start-up steps of rbd, overset, pimple, total and
the overset parts, then the median over the rounds; overset share of total;
peak memory (median over the rounds); the speed-ups of the stencil update
with the mesh motion (oversetMovePoints) over inverseDistance and
trackingInverseDistance of the same level and ranks, and the memory ratio
to inverseDistance) and PREFIX.png (stacked bars of the medians, and the peak memory).
"""

import argparse
import os
import platform
import time

import numpy as np

from flapfoam.plots.backend import pyplot
from flapfoam.io import step_timers
from flapfoam.errors import run_tool


# The stock solver with the paper's settings (-settings): the reference of
# the "step: stock / this" column
STOCK = "inverseDistance+paper+stockInterpolation"


def median_columns(case, startup):
    columns, data = step_timers.read_input(
        os.path.join(case, "postProcessing", "stepTimers"), startup)
    return {c: float(np.median(data[:, i])) for i, c in enumerate(columns)}, \
        len(data)


def read_rows(folder, runs, startup):
    """One row per configuration (level, ranks, stencil or stencil+settings:
    the run's name level-np<N>-<configuration>-r<round>): the medians over
    the rounds of the per-run medians, the overset range, peak memory."""
    # Per configuration, the per-run medians of every round
    groups = {}
    for run in runs:
        level, np_, stencil = run.rsplit("-r", 1)[0].split("-", 2)
        med, n = median_columns(os.path.join(folder, run), startup)
        with open(os.path.join(folder, run + ".memory")) as f:
            mem = float(f.read().split()[0])
        g = groups.setdefault((level, int(np_[2:]), stencil), [])
        g.append(dict(med=med, n=n, mem=mem))

    rows = []
    for (level, np_, stencil), g in groups.items():
        columns = set.intersection(*(set(r["med"]) for r in g))
        med = {c: float(np.median([r["med"][c] for r in g])) for c in columns}
        spread = [r["med"]["overset"] for r in g]
        rows.append(dict(level=level, np=np_, stencil=stencil, med=med,
                         n=g[0]["n"], rounds=len(g),
                         mem=float(np.median([r["mem"] for r in g])),
                         spread=(min(spread), max(spread))))

    return rows


def table(rows, startup):
    """The markdown lines of the table."""
    base = {(r["level"], r["np"]): r for r in rows
            if r["stencil"] == "inverseDistance"}
    tracking = {(r["level"], r["np"]): r for r in rows
                if r["stencil"] == "trackingInverseDistance"}
    stock = {(r["level"], r["np"]): r for r in rows
             if r["stencil"] == STOCK}

    def stock_ratio(r):
        """The stock solver's step (STOCK) over r's"""
        ref = stock.get((r["level"], r["np"]))
        return "%.2f" % (ref["med"]["total"]/r["med"]["total"]) if ref \
            else "-"

    def speedup(ref, r):
        """Stencil update with the motion: ref's time over r's"""
        if not ref:
            return "-"
        return "%.1f" % (ref["med"]["oversetMovePoints"]
                         / r["med"]["oversetMovePoints"])

    lines = [
        "# Overset stencils on the single-wing drone: time per step",
        "",
        "Median per step after %d start-up steps (wall-clock seconds; in "
        "parallel the maximum over ranks), `cases/singleWingDrone`, eABA "
        "multibody motion, fixed time step 1e-5 s.  overset = stencil "
        "update with the mesh motion (`oversetMovePoints`), addressing and "
        "field interpolation after the motion; pimple includes the overset "
        "interpolation inside the PIMPLE loop.  Peak memory: the solver "
        "processes' peak resident memory, summed over the ranks.  Ratios "
        "are to the runs at the same level and ranks.  Speed-up: the "
        "stencil update with the mesh motion (`oversetMovePoints`: the "
        "stock stencils have no timer of their own inside it) of "
        "inverseDistance (ID) or trackingInverseDistance (tracking) over "
        "this run's.  step: stock / this: the whole step of the stock "
        "solver with the paper's settings (%s, run with "
        "-settings) over this configuration's.  With several rounds: "
        "medians over the rounds, and "
        "the overset range over the rounds."
        % (startup, STOCK),
        "",
        "| level | ranks | stencil | steps x rounds | rbd [s] | "
        "overset [s] (range) | stencil+motion [s] | pimple [s] | total [s] "
        "| overset share | peak memory [MiB] | speed-up vs ID | speed-up vs "
        "tracking | memory vs ID | step: stock / this |",
        "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        "---:|---:|",
    ]
    for r in rows:
        m = r["med"]
        key = (r["level"], r["np"])
        b = base.get(key)
        mratio = "%.2f" % (r["mem"]/b["mem"]) if b else "-"
        lines.append(
            "| %s | %d | %s | %d x %d | %.4f | %.3f (%.3f-%.3f) | %.3f | "
            "%.3f | %.3f | %.0f %% | %.0f | %s | %s | %s | %s |" % (
                r["level"], r["np"], r["stencil"], r["n"], r["rounds"],
                m["rbd"], m["overset"], r["spread"][0], r["spread"][1],
                m.get("oversetMovePoints", float("nan")),
                m["pimple"], m["total"], 100*m["overset"]/m["total"],
                r["mem"], speedup(b, r), speedup(tracking.get(key), r),
                mratio, stock_ratio(r)))
    lines += pimple_table(rows)
    lines += [
        "",
        "Machine: %s, %d CPUs, load average %s; %s." % (
            platform.node(), os.cpu_count(),
            " ".join("%.2f" % x for x in os.getloadavg()),
            time.strftime("%Y-%m-%d %H:%M")),
    ]
    return lines


def pimple_table(rows):
    """The pimple column split (step_timers.pimple_split) of the rows that
    have it: the markdown lines."""
    split = [(r, step_timers.pimple_split(r["med"])) for r in rows]
    split = [(r, s) for r, s in split if s]
    if not split:
        return []
    lines = [
        "",
        "Where pimple goes (medians per step, seconds; the fvOption "
        "`pimpleTimers`): momentum = assembly + solve, pressure = the "
        "correctors (of which the solves), turbulence = `correct()` + its "
        "solves (and the writes, flightData), the overset interpolations "
        "inside PIMPLE (calls a step), pressure iterations a step.",
        "",
        "| level | ranks | stencil | pimple [s] | momentum | pressure "
        "(solves) | turbulence | interpolate (calls) | rest | p iterations |",
        "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r, s in split:
        lines.append(
            "| %s | %d | %s | %.3f | %.3f | %.3f (%.3f) | %.3f | %.3f (%.0f) "
            "| %.3f | %.0f |" % (
                r["level"], r["np"], r["stencil"], r["med"]["pimple"],
                s["momentum"], s["pressure"], s["pressureSolve"],
                s["turbulence"], s["interpolate"], s["interpolations"],
                s["rest"], s["pIterations"]))
    return lines


def chart(rows, png):
    """Stacked bars of the medians and the peak memory."""
    plt = pyplot()

    fig, (ax, axm) = plt.subplots(
        2, 1, figsize=(max(6, 1.1*len(rows)), 7.5), sharex=True,
        gridspec_kw=dict(height_ratios=(2, 1)))
    x = np.arange(len(rows))
    bottom = np.zeros(len(rows))
    for part, colour in (("rbd", "tab:green"), ("overset", "tab:red"),
                         ("pimple", "tab:blue")):
        v = np.array([r["med"][part] for r in rows])
        ax.bar(x, v, bottom=bottom, color=colour, label=part)
        bottom += v
    ax.set_ylabel("median time per step [s]")
    ax.set_title("single-wing drone: where a time step goes")
    ax.legend()
    axm.bar(x, [r["mem"] for r in rows], color="tab:gray")
    axm.set_ylabel("peak memory [MiB]\n(sum over ranks)")
    axm.set_xticks(x)
    axm.set_xticklabels(["%s\nnp %d\n%s" % (r["level"], r["np"],
                         r["stencil"].replace("InverseDistance", "ID"))
                         for r in rows], fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-dir", required=True)
    parser.add_argument("-startup", type=int, default=3)
    parser.add_argument("-o", default="results")
    parser.add_argument("runs", nargs="+")
    args = parser.parse_args()

    rows = read_rows(args.dir, args.runs, args.startup)
    lines = table(rows, args.startup)
    with open(args.o + ".md", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    chart(rows, args.o + ".png")
    print("summarise: wrote %s.md, %s.png" % (args.o, args.o))


if __name__ == "__main__":
    run_tool(main)
