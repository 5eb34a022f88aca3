# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
flapfoam: the Python side of flapFoam, one package for the cases, the
benchmarks and the tests (numpy; scipy, h5py and matplotlib where a module
says so).  Only the plot modules import matplotlib.

    foamDict        OpenFOAM dictionaries, rigidBodyMotionState
    tables          per-step tables (joints.dat, bodies.dat) joined over
                    restarts, time folders
    wang            Wang kinematics of imposedMotion entries
    flightData      HDF5 flight data: find, load, check, compare
    stepTimers      stepTimers.dat: read, join, summarise
    mpiCounts       MPI counts per rank (libflapFoamMPICounters.so): read,
                    totals, per-step difference of two runs
    foamMesh        polyMesh and volScalarField reader
    wingGeometry    the semi-elliptical wing (docs/paper.md, Table 1)
    blockMesh       blockMeshDict writer, 1-D cell distributions
    wingMesh        the wing component mesh and its levels
    backgroundMesh  the background cube and its refinement regions
    meshGen         the command line and output of the cases' meshGen.py
    checks          PASS/FAIL lines
    checkRun        checks of drone runs (prescribed joints, timers, ...)
    meshChecks      checks of the wing's overset mesh and its orphans
    plotting        matplotlib set-up and the plots the cases share
    plotStepTimers  the step-timer bar chart
    plotSingleWing  plots of a single-wing drone run
    plotBodyWing    plots of a body-wing drone run

The package is found through PYTHONPATH, which etc/bashrc sets once
($FLAPFOAM_PROJECT_DIR/scripts); no script edits sys.path.  Run a tool as
python3 -m flapfoam.<tool>; the cases' and benches' scripts import from
here.
"""
