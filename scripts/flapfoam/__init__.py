# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
flapfoam: the Python side of flapFoam, one package for the cases, the
benchmarks and the tests (numpy; scipy, h5py and matplotlib where a module
says so).  Only the plot modules import matplotlib.

Modules (PEP 8 names; the tools run as flapfoam <module>, which is
$FLAPFOAM_PYTHON -m flapfoam <module>; flapfoam -help lists them):

  errors
    errors            FlapFoamError, the package's one error, and run_tool,
                      every tool's main guard (the message, exit status 1)
  readers
    foam_dict         OpenFOAM dictionaries, rigidBodyMotionState
    foam_mesh         polyMesh and volScalarField reader
    tables            per-step tables (joints.dat, bodies.dat) joined over
                      restarts, time folders
    flight_data       HDF5 flight data: find, load, check, compare
    step_timers       stepTimers.dat: read, join, summarise
    solver_log        the per-step numbers of the solver's log
    mpi_counts        MPI counts per rank (libflapFoamMPICounters.so)
    mpi_counts_checks the mpiCounters Alltest's checks of those counts
  references and models
    wang              Wang kinematics of imposedMotion entries
    quasi_steady      the quasi-steady blade-element wing's reference
    chain_reference   planar chains by Lagrange's equations (scipy)
    double_pendulum   the double pendulum case's metrics against its
                      Lagrangian reference (its Alltest's checks)
    scaling_model     the per-rank model of a step (bench/scaling)
    forward_dynamics_table  bench/forwardDynamics' table
  meshes
    wing_geometry     the semi-elliptical wing (docs/paper.md, Table 1)
    block_mesh        blockMeshDict writer, 1-D cell distributions
    wing_mesh         the wing component mesh and its levels
    background_mesh   the background cube and its refinement regions
    mesh_gen          the command line and output of the cases' meshGen.py
  checks and studies
    checks            PASS/FAIL lines
    result_checks     the result checks of the Alltest scripts
    check_run         checks of drone runs (prescribed joints, timers, ...)
    mesh_checks       checks of the wing's overset mesh and its orphans
    integrator_order  the integrators' observed order in deltaT
    grid_study        the grid study: Richardson, GCI
    pimple_guard      the PIMPLE study's accuracy guard
    pimple_study      the PIMPLE study's table
    qs_sweep          kinematics sweeps of the quasi-steady model
    qs_calibrate      the quasi-steady wing calibrated on a CFD run
    gain_sweep        gain sweeps of the flight controller
    compare_models    a CFD run against its quasi-steady run
    authors_control   the paper authors' controllers as flapFoam entries
    rank_tables       per-rank tables of a decomposition
    scaling_causes    why one partition's PIMPLE costs more
    scaling_validate  the scaling model against timed runs (and its
                      command line)
    scaling_summary   bench/scaling's tables and charts (scaling_report,
                      scaling_charts)
    scaling_bound     bench/scaling's bound stage: a pose's decomposition
    timed_rounds      the portable stage's timed runs
    overset_summary   bench/overset's table and chart
    peak_memory       a command's peak memory, summed over its processes
    qs_integrators    the paper's integrator study on the quasi-steady model
    ascent            a production ascent's results against the paper's
    doc_commands      the README's and docs' shell blocks run as typed
  plots
    backend           matplotlib's one set-up (pyplot, Agg)
    plotting          the plots the cases share
    plot_step_timers  the step-timer bar chart
    plot_single_wing  plots of a single-wing drone run
    plot_body_wing    plots of a body-wing drone run
    plot_double_pendulum  the double pendulum case's figures
    control_plot      the closed-loop flight of controlled runs

The package is found through PYTHONPATH, which etc/bashrc sets once
($FLAPFOAM_PROJECT_DIR/scripts); no script edits sys.path.  Run a tool as
flapfoam <tool> (bin/flapfoam, on the PATH from etc/bashrc: the interpreter
of FLAPFOAM_PYTHON, whatever python3 comes first on the PATH); the cases'
and benches' scripts import from here.
"""
