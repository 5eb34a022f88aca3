#!/usr/bin/python3
"""Table and chart of the overset stencil benchmark (bench/overset/run).

    bench/overset/summarise.py -dir DIR [-startup K] [-o PREFIX] RUN [RUN ...]

Each RUN is DIR/<level>-np<N>-<stencil>, a case run by
cases/singleWingDrone/Allrun, with DIR/<RUN>.memory from peakMemory.py.
Writes PREFIX.md (markdown table: median per step after K start-up steps of
rbd, overset, pimple, total and the overset parts; overset share of total;
peak memory; the ratios to the inverseDistance run of the same level and
ranks) and PREFIX.png (stacked bars of the medians).
"""

import argparse
import os
import platform
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
import plotStepTimers  # noqa: E402


def median_columns(case, startup):
    columns, data = plotStepTimers.read_input(
        os.path.join(case, "postProcessing", "stepTimers"), startup)
    return {c: float(np.median(data[:, i])) for i, c in enumerate(columns)}, \
        len(data)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-dir", required=True)
    parser.add_argument("-startup", type=int, default=3)
    parser.add_argument("-o", default="results")
    parser.add_argument("runs", nargs="+")
    args = parser.parse_args()

    rows = []
    for run in args.runs:
        level, np_, stencil = run.split("-", 2)
        med, n = median_columns(os.path.join(args.dir, run), args.startup)
        with open(os.path.join(args.dir, run + ".memory")) as f:
            mem = float(f.read().split()[0])
        rows.append(dict(run=run, level=level, np=int(np_[2:]),
                         stencil=stencil, med=med, n=n, mem=mem))

    base = {(r["level"], r["np"]): r for r in rows
            if r["stencil"] == "inverseDistance"}

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
        "are to inverseDistance at the same level and ranks."
        % args.startup,
        "",
        "| level | ranks | stencil | steps | rbd [s] | overset [s] | "
        "stencil+motion [s] | pimple [s] | total [s] | overset share | "
        "peak memory [MiB] | overset vs inverseDistance | memory vs "
        "inverseDistance |",
        "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        m = r["med"]
        b = base.get((r["level"], r["np"]))
        ratio = "%.2f" % (m["overset"]/b["med"]["overset"]) if b else "-"
        mratio = "%.2f" % (r["mem"]/b["mem"]) if b else "-"
        lines.append(
            "| %s | %d | %s | %d | %.4f | %.3f | %.3f | %.3f | %.3f | "
            "%.0f %% | %.0f | %s | %s |" % (
                r["level"], r["np"], r["stencil"], r["n"], m["rbd"],
                m["overset"], m.get("oversetMovePoints", float("nan")),
                m["pimple"], m["total"], 100*m["overset"]/m["total"],
                r["mem"], ratio, mratio))
    lines += [
        "",
        "Machine: %s, %d CPUs, load average %s; %s." % (
            platform.node(), os.cpu_count(),
            " ".join("%.2f" % x for x in os.getloadavg()),
            time.strftime("%Y-%m-%d %H:%M")),
    ]
    with open(args.o + ".md", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(max(6, 1.1*len(rows)), 4.5))
    x = np.arange(len(rows))
    bottom = np.zeros(len(rows))
    for part, colour in (("rbd", "tab:green"), ("overset", "tab:red"),
                         ("pimple", "tab:blue")):
        v = np.array([r["med"][part] for r in rows])
        ax.bar(x, v, bottom=bottom, color=colour, label=part)
        bottom += v
    ax.set_xticks(x)
    ax.set_xticklabels(["%s\nnp %d\n%s" % (r["level"], r["np"],
                        r["stencil"].replace("InverseDistance", "ID"))
                        for r in rows], fontsize=8)
    ax.set_ylabel("median time per step [s]")
    ax.set_title("single-wing drone: where a time step goes")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.o + ".png", dpi=120)
    print("summarise: wrote %s.md, %s.png" % (args.o, args.o))


if __name__ == "__main__":
    main()
