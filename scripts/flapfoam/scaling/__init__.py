# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
bench/scaling's model and reports: the per-rank model of a step (model),
why one partition costs more (causes), the model against timed runs
(validate) and on sessions held out from its fit (holdout), the tables and
charts (summary, report, charts) and a pose's
decomposition bound (bound).  Its tools are flapfoam scaling_<module>.
"""

TOOL_PREFIX = "scaling_"
