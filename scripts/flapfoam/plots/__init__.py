# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Plots (matplotlib, Agg, set up once in backend): the plots the cases share
(plotting), the step-timer chart (step_timers), the drones' runs (drone:
single-wing and body-wing, each with its own panels), the double pendulum
(double_pendulum), the closed-loop flight of controlled runs
(control) and a CFD run's vortices and overset mesh rendered by ParaView
(flow; _pv_render is its pvbatch script).  Its tools are
flapfoam plot_<module>.
"""

TOOL_PREFIX = "plot_"
