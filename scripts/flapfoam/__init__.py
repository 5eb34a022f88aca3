# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
flapfoam: the Python side of flapFoam, one package for the cases, the
benchmarks and the tests (numpy; scipy, h5py and matplotlib where a module
says so).  Only the plot modules import matplotlib.

Subpackages, by concern (each one's docstring lists its modules):

  io        reading and writing OpenFOAM's files and the runs' data
  models    references and models (Wang kinematics, quasi-steady wing,
            Lagrangian chains, the paper's wing, the authors' controllers)
  mesh      mesh generation (blockMeshDict, the wing, the background)
  checks    PASS/FAIL checks of runs, meshes, counts, docs and studies
  studies   studies over many runs (order, grid, PIMPLE, QS sweeps and
            calibration, gains, CFD against QS, the production ascent)
  scaling   bench/scaling's model and reports (tools scaling_<module>)
  bench     benchmark helpers (rank tables, timed rounds, peak memory)
  plots     matplotlib plots, set up once in plots.backend (tools
            plot_<module>)

and, at the top, errors (FlapFoamError, the package's one error, and
run_tool, every tool's main guard: the message, exit status 1) and paths
(the project's folder).  A tool is a module with a main guard: flapfoam
TOOL runs it ($FLAPFOAM_PYTHON -m flapfoam TOOL); flapfoam -help lists them.

The package is found through PYTHONPATH, which etc/bashrc sets once
($FLAPFOAM_PROJECT_DIR/scripts); no script edits sys.path.  Run a tool as
flapfoam <tool> (bin/flapfoam, on the PATH from etc/bashrc: the interpreter
of FLAPFOAM_PYTHON, whatever python3 comes first on the PATH); the cases'
and benches' scripts import from here.
"""
