# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Reading and writing OpenFOAM's files and the runs' data: dictionaries
(foam_dict), polyMesh and fields (foam_mesh), the per-step tables joined over
restarts (tables), the HDF5 flight data (flight_data), a run's time series
in one dataclass from either (run_series), the step timers
(step_timers), the solver's log (solver_log) and the MPI counts (mpi_counts).
"""
