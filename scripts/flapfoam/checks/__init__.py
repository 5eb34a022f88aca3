# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Checks, each printing PASS/FAIL lines (flapfoam.harness.checklist): of drone
runs (check_run), of the wing's overset mesh (mesh_checks), of the Alltest
scripts' results (result_checks), of the MPI counts (mpi_counts_checks), of
the double pendulum (double_pendulum), of the overset cell types, motion and
rank report (overset_*) and the PIMPLE study's accuracy guard (pimple_guard).
"""
