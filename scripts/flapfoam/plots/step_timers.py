# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Bar chart of where each time step's wall-clock time goes (stepTimers).

    flapfoam plot_step_timers [options] INPUT [INPUT ...]

Each INPUT is a stepTimers.dat written by the stepTimers function object, or
a directory (a case, its postProcessing/ or postProcessing/<name>/) searched
for stepTimers.dat files; the files found under one directory (one per
start time, i.e. restarts) are joined in time order.  Each INPUT gives one
stacked bar: the mean per step of rbd, overset and pimple (the profiling bar
chart of the paper), with "other" (total - rbd - overset - pimple) on top.
With -fine the overset bar is split into its overset* parts.

Prints per input: the number of steps, the mean and median per step of
every column and its share of total, and the closure check: the largest
|rbd + overset + pimple - total|/total over the steps.

Options:
    -o PNG                the chart (default stepTimers.png)
    -n, -nStartup N      rows skipped at the start of each file (default 2,
                          as the function object's summary)
    -l TEXT               bar label, once per INPUT (default: the path)
    -fine                split overset into its parts
    -title TEXT          chart title

Exits non-zero if an input holds no steps after the start-up rows.

Uses Debian's python (/usr/bin/python3) with numpy and matplotlib.
"""

import argparse
import os
import sys
from dataclasses import dataclass

import numpy as np

from flapfoam.plots.backend import pyplot
from flapfoam.io.step_timers import (GROUPS, find_files, read_input,
                                     read_ranks, slowest_rank_tree, summary)
from flapfoam.errors import run_tool


@dataclass
class Chart:
    """Where the chart goes and what it shows: the PNG, its title (None: the
    default), the overset part's own parts (fine)."""
    output: str = "stepTimers.png"
    title: str = None
    fine: bool = False


def plot(labels, means, columns_list, args):
    """The stacked bars of the step's parts (args: a Chart)."""
    plt = pyplot()

    fig, ax = plt.subplots(figsize=(2.0 + 1.6*len(labels), 4.8))
    x = np.arange(len(labels))
    colors = {"rbd": "tab:green", "overset": "tab:red",
              "pimple": "tab:blue", "other": "lightgrey"}
    overset_parts = []
    if args.fine:
        for columns in columns_list:
            for c in columns:
                if c.startswith("overset") and c not in overset_parts \
                        and c != "overset":
                    overset_parts.append(c)
    segments = ["rbd"] + (overset_parts or ["overset"]) + ["pimple", "other"]
    reds = plt.get_cmap("Reds")
    for i, p in enumerate(overset_parts):
        colors[p] = reds(0.45 + 0.5*i/max(len(overset_parts) - 1, 1))

    bottom = np.zeros(len(labels))
    for seg in segments:
        h = np.array([max(m.get(seg, 0.0), 0.0) for m in means])
        if not h.any():
            continue
        ax.bar(x, h, 0.6, bottom=bottom, color=colors[seg], label=seg,
               edgecolor="black", linewidth=0.5)
        for xi, hi, bi, m in zip(x, h, bottom, means):
            share = hi/m["total"] if m["total"] > 0 else 0
            if share > 0.04:
                ax.text(xi, bi + hi/2, "%.0f%%" % (100*share),
                        ha="center", va="center", fontsize=8)
        bottom += h

    ax.set_xticks(x)
    ax.set_xticklabels(labels, rotation=15 if len(labels) > 2 else 0,
                       fontsize=8)
    ax.set_ylabel("wall-clock time per step [s]")
    ax.set_title(args.title or "Where a time step's time goes")
    handles, names = ax.get_legend_handles_labels()
    ax.legend(handles[::-1], names[::-1], fontsize=8, loc="upper left",
              bbox_to_anchor=(1.0, 1.0))
    fig.tight_layout()
    fig.savefig(args.output, dpi=150)
    print("plot_step_timers: wrote " + args.output)


def chart(inputs, labels, n_startup, out):
    """The chart (out: a Chart) of the runs' step timers (inputs: a
    postProcessing/stepTimers folder or a stepTimers.dat each, labels one
    each) after n_startup start-up steps; ValueError if one has no steps."""
    means = []
    columns_list = []
    for label, path in zip(labels, inputs):
        columns, data = read_input(path, n_startup)
        missing = [c for c in ["time"] + GROUPS if c not in columns]
        if len(data) == 0 or missing:
            raise ValueError("%s: no steps after %d start-up rows%s"
                             % (path, n_startup,
                                (", missing " + " ".join(missing))
                                if columns else ""))
        means.append(summary(label, columns, data, n_startup))
        slowest_rank_tree(label, [r for f in find_files(path) for r in
                                  read_ranks(os.path.join(
                                      os.path.dirname(f),
                                      "stepTimersRanks.dat"))])
        columns_list.append(columns)
    plot(labels, means, columns_list, out)


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("inputs", nargs="+", metavar="INPUT")
    parser.add_argument("-o", dest="output", default="stepTimers.png")
    parser.add_argument("-n", "-nStartup", dest="n_startup", type=int,
                        default=2)
    parser.add_argument("-l", dest="label", action="append")
    parser.add_argument("-fine", action="store_true")
    parser.add_argument("-title")
    args = parser.parse_args(argv)

    if args.n_startup < 0:
        parser.error("-nStartup must be >= 0")
    labels = args.label or []
    if labels and len(labels) != len(args.inputs):
        parser.error("give -l once per INPUT")
    labels = labels or [os.path.normpath(p) for p in args.inputs]

    try:
        chart(args.inputs, labels, args.n_startup,
              Chart(args.output, args.title, args.fine))
    except ValueError as e:
        sys.exit("plot_step_timers: %s" % e)

if __name__ == "__main__":
    run_tool(main)

