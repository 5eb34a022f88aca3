# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
matplotlib's one set-up in the package: pyplot with the Agg backend (PNG
files, no display), imported when a plot is made, so that the modules
that plot only on request load without matplotlib.
"""


def pyplot():
    """matplotlib.pyplot with the Agg backend."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt
