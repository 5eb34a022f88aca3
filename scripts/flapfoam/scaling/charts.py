# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The charts of the scaling bench (flapfoam.scaling.summary's data), for each level of
-levels: PREFIX-<level>-step.png (the model's step against ranks per method,
one panel per stencil, with the timed runs), PREFIX-<level>-split.png (its
rbd/overset/pimple split per method and stencil), PREFIX-remote.png (the
remote acceptor and pair shares against ranks, every level) and PREFIX-<level>-48.png
(the paper's bar chart: a step at 48 ranks per method, split)."""

import os

from flapfoam.plots.plotting import plt, save

METHODS = ["simple", "hierarchical", "scotch", "metis", "oversetGraph"]
SHORT = {"inverseDistance": "ID", "octreeInverseDistance": "octree"}
PARTS = ("rbd", "overset", "pimple")
COLOURS = {"rbd": "tab:gray", "overset": "tab:red", "pimple": "tab:blue"}


def _series(model, level, method, stencil):
    keys = sorted(p for (lv, m, p, s) in model
                  if lv == level and m == method and s == stencil)
    return keys, [model[(level, method, p, stencil)] for p in keys]


def step_chart(data, level, out):
    model = data["model"]
    fig, axes = plt.subplots(1, len(data["stencils"]), squeeze=False,
                             figsize=(6*len(data["stencils"]), 4.5))
    for ax, stencil in zip(axes[0], data["stencils"]):
        serial = model[(level, "serial", 1, stencil)]["total"]
        for method in METHODS:
            p, steps = _series(model, level, method, stencil)
            if p:
                line, = ax.plot(p, [s["total"] for s in steps], "o-",
                                label=method)
                ax.plot(p, [s["overset"] for s in steps], ":",
                        color=line.get_color())
        ax.plot([1], [serial], "ks", label="serial (model)")
        for (method, p, s), t in data["timed"].get(level, {}).items():
            if s == stencil:
                ax.plot([p], [t["total"]], "kx")
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xlabel("ranks")
        ax.set_ylabel("step [s] (solid: total, dotted: overset)")
        ax.set_title("SW %s, %s: model (x: timed here)" % (level,
                                                           SHORT[stencil]))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    save(fig, os.path.dirname(out), os.path.basename(out))


def split_chart(data, level, out):
    model = data["model"]
    stencils = data["stencils"]
    fig, axes = plt.subplots(len(stencils), len(METHODS), squeeze=False,
                             figsize=(3.2*len(METHODS), 3*len(stencils)),
                             sharey="row")
    for row, stencil in zip(axes, stencils):
        for ax, method in zip(row, METHODS):
            p, steps = _series(model, level, method, stencil)
            if not p:
                continue
            ax.stackplot(range(len(p)), *[[s[k] for s in steps]
                                          for k in PARTS],
                         labels=PARTS, colors=[COLOURS[k] for k in PARTS])
            ax.set_xticks(range(len(p)))
            ax.set_xticklabels(p)
            ax.set_title("%s, %s" % (method, SHORT[stencil]), fontsize=9)
            ax.set_xlabel("ranks")
        row[0].set_ylabel("step [s] (model)")
    axes[0][0].legend(fontsize=8)
    fig.suptitle("SW %s: rbd / overset / pimple of a step (model)" % level)
    save(fig, os.path.dirname(out), os.path.basename(out))


def remote_chart(data, out):
    levels = sorted(data["structure"])
    fig, axes = plt.subplots(1, len(levels), squeeze=False,
                             figsize=(5*len(levels), 4), sharey=True)
    for ax, level in zip(axes[0], levels):
        st = data["structure"][level]
        for method in METHODS:
            p = sorted(n for (m, n) in st if m == method)
            if p:
                line, = ax.plot(p, [100*st[(method, n)].remote_acceptor_share()
                                    for n in p], "o-", label=method)
                ax.plot(p, [100*st[(method, n)].remote_pair_share()
                            for n in p], ":", color=line.get_color())
        ax.axhline(20, color="k", ls="--", lw=0.8)
        ax.set_xscale("log", base=2)
        ax.set_xlabel("ranks")
        ax.set_title("SW %s" % level)
        ax.grid(True, alpha=0.3)
    axes[0][0].set_ylabel("remote acceptors (solid), pairs (dotted) [%]")
    axes[0][0].legend(fontsize=8)
    save(fig, os.path.dirname(out), os.path.basename(out))


def bars48(data, level, out, ranks=48):
    model = data["model"]
    fig, ax = plt.subplots(figsize=(9, 4.5))
    x, labels = 0, []
    for stencil in data["stencils"]:
        for method in METHODS:
            s = model.get((level, method, ranks, stencil))
            if s is None:
                continue
            bottom = 0.0
            for k in PARTS:
                ax.bar(x, s[k], bottom=bottom, color=COLOURS[k],
                       label=k if x == 0 else None)
                bottom += s[k]
            ax.text(x, bottom, "%.2f" % bottom, ha="center", va="bottom",
                    fontsize=8)
            labels.append("%s\n%s" % (method, SHORT[stencil]))
            x += 1
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylabel("step [s] (model)")
    ax.set_title("SW %s at %d ranks: a step per decomposition (model)"
                 % (level, ranks))
    ax.legend()
    save(fig, os.path.dirname(out), os.path.basename(out))


def write_all(data, prefix):
    for level in data["levels"]:
        step_chart(data, level, "%s-%s-step.png" % (prefix, level))
        split_chart(data, level, "%s-%s-split.png" % (prefix, level))
        if any(k[0] == level and k[2] == 48 for k in data["model"]):
            bars48(data, level, "%s-%s-48.png" % (prefix, level))
    remote_chart(data, prefix + "-remote.png")
