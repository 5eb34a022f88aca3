# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
What the plots of the cases share: matplotlib with the Agg backend (only
plot modules import this one), saving a figure, the shaded downstrokes and
the step-timer chart of a run (scripts/plotStepTimers.py).
"""

import os
import subprocess
import sys

import numpy as np

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (the plot modules' plt)

PLOT_STEP_TIMERS = os.path.join(
    os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
    "plotStepTimers.py")


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=120)
    plt.close(fig)


def shadeDownstrokes(ax, t, qDot):
    """Shade the intervals where phi decreases (qDot < 0)."""
    down = qDot < 0
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


def stepTimers(case, out, label):
    """stepTimers.png of the run's postProcessing/stepTimers (if any) by
    scripts/plotStepTimers.py; its exit status."""
    timers = os.path.join(case, "postProcessing", "stepTimers")
    if not os.path.isdir(timers):
        return 0
    return subprocess.call([sys.executable, PLOT_STEP_TIMERS, timers, "-o",
                            os.path.join(out, "stepTimers.png"), "-l",
                            label])
