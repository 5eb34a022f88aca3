# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
What the plots of the cases share: pyplot (flapfoam.plots.backend; only plot
modules import this one), saving a figure, an x-z path, the axes of a
plot over the cycles, the shaded downstrokes and the step-timer chart of a
run (flapfoam.plots.step_timers).
"""

import os

import textwrap

import numpy as np

from flapfoam.plots import step_timers as plot_step_timers
from flapfoam.plots.backend import pyplot
from flapfoam.io.step_timers import read_input

plt = pyplot()                  # the plot modules' plt


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=120)
    plt.close(fig)


def path(x, z, t, labels, **line):
    """The figure of an x-z path [mm] from its start (o) to its end (s);
    labels: the x and z axes' and the title (wrapped to the figure's
    width: a model's coefficients make it long)."""
    fig, ax = plt.subplots(figsize=(6, 5))
    ax.plot(1e3*x, 1e3*z, "-", **line)
    ax.plot(1e3*x[0], 1e3*z[0], "o", label="t = %.4g s" % t[0])
    ax.plot(1e3*x[-1], 1e3*z[-1], "s", label="t = %.4g s" % t[-1])
    ax.set_xlabel(labels[0])
    ax.set_ylabel(labels[1])
    ax.set_title(textwrap.fill(labels[2], 56), fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    return fig


def cycle_axes(ax, ylabel, title, xlabel="t f [cycles]"):
    """The zero line, the labels against t f and the grid of a plot over
    the cycles."""
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, alpha=0.3)


def shade_downstrokes(ax, t, q_dot):
    """Shade the intervals where phi decreases (qDot < 0)."""
    down = q_dot < 0
    if not down.any():
        return
    edges = np.flatnonzero(np.diff(down.astype(int))) + 1
    bounds = np.concatenate([[0], edges, [len(t)]])
    first = True
    for a, b in zip(bounds[:-1], bounds[1:]):
        if down[a]:
            ax.axvspan(t[a], t[min(b, len(t) - 1)], color="0.88", lw=0,
                       label="downstroke" if first else None)
            first = False


def step_timers_chart(case, out, label):
    """stepTimers.png of the run's postProcessing/stepTimers (if any), the
    chart of flapfoam.plots.step_timers; 0, or 1 if it has no steps."""
    timers = os.path.join(case, "postProcessing", "stepTimers")
    if not os.path.isdir(timers):
        return 0
    if len(read_input(timers, 2)[1]) == 0:
        print("plotRun: no step-timer plot: no step after the 2 start-up"
              " steps")
        return 0
    try:
        plot_step_timers.chart([timers], [label], 2, plot_step_timers.Chart(
            os.path.join(out, "stepTimers.png")))
    except ValueError as e:
        print("plotRun: no step-timer plot: %s" % e)
        return 1
    return 0
