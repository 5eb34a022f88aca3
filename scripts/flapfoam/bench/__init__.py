# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Benchmark helpers: per-rank tables of a decomposition (rank_tables), the
portable archive's timed runs (timed_rounds), a command's peak memory
(peak_memory) and bench/overset's table (overset_summary).
"""
