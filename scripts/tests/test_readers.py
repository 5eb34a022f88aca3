# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The readers of the flapfoam package: OpenFOAM dictionaries and states
(foamDict), per-step tables joined over restarts (tables), the solver's
log (solverLog)."""

import math

import pytest

from flapfoam.io import foam_dict

from flapfoam.io import solver_log

from flapfoam.io import tables
HEADER = """/*--------------------------------*- C++ -*---------*\\
  a banner
\\*---------------------------------------------------*/
FoamFile { version 2.0; format ascii; class dictionary; object x; }
"""


def write(path, text):
    path.write_text(text)
    return str(path)


def test_dictionary_nesting_lists_and_comments(tmp_path):
    d = foam_dict.read_foam_dict(write(tmp_path / "d", HEADER + """
solver { type Newmark; }   // a comment
g (0 0 -9.81);
/* a block
   comment */
bodies
{
    wing { mass 1.5e-3; transform (1 0 0 0 1 0 0 0 1) (0 0 0); }
}
name "quoted words";
"""))
    assert d["solver"] == {"type": ["Newmark"]}
    assert d["g"] == ["(", "0", "0", "-9.81", ")"]
    assert d["bodies"]["wing"]["mass"] == ["1.5e-3"]
    assert d["bodies"]["wing"]["transform"].count("(") == 2
    assert d["name"] == ['"quoted words"']


def test_multibody_coeffs_of_either_layout(tmp_path):
    top = write(tmp_path / "a", HEADER + "nIter 3;\n")
    sub = write(tmp_path / "b", HEADER
                + "eABAMeshMotionCoeffs { nIter 2; }\nother 1;\n")
    assert foam_dict.multibody_coeffs(top)["nIter"] == ["3"]
    assert foam_dict.multibody_coeffs(sub) == {"nIter": ["2"]}


def test_state_of_a_run_and_a_hand_written_one(tmp_path):
    run = foam_dict.read_state(write(tmp_path / "s1", HEADER + """
t 0.0125; deltaT 1.2e-05;
q 2(0.1 -0.2); qDot 2(1 2); qDdot 2(3 4);
"""))
    assert run["t"] == 0.0125
    assert list(run["q"]) == [0.1, -0.2] and list(run["qDdot"]) == [3, 4]
    hand = foam_dict.read_state(write(tmp_path / "s2", HEADER
                                    + "q (0.3 0.1); qDot (1 0);\n"))
    assert list(hand["q"]) == [0.3, 0.1]
    assert "qDdot" not in hand and "t" not in hand


def test_table_joined_over_a_restart(tmp_path):
    base = tmp_path / "postProcessing" / "eABAMeshMotion"
    for t0, rows in (("0", [(0, 1), (1, 2), (2, 3), (3, 4)]),
                     ("2", [(2, 30), (3, 40), (4, 50)])):
        (base / t0).mkdir(parents=True)
        (base / t0 / "joints.dat").write_text(
            "# time q_0\n" + "".join("%g %g\n" % r for r in rows))
    columns, data = tables.joined_table(str(base), "joints.dat", False)
    assert columns == ["time", "q_0"]
    assert data.tolist() == [[0, 1], [1, 2], [2, 30], [3, 40], [4, 50]]
    _, kept = tables.joined_table(str(base), "joints.dat", True)
    assert kept[:, 1].tolist() == [1, 2, 3, 40, 50]
    assert tables.time_value("0.0125") == 0.0125
    assert tables.time_value("constant", -1) == -1


LOG = """Starting time loop

Courant Number mean: 0 max: 0
Time = 1e-05

smoothSolver:  Solving for Ux, Initial residual = 1, Final residual = 1e-9, No Iterations 2
DILUPBiCGStab:  Solving for p, Initial residual = 1, Final residual = 0.009, No Iterations 30
time step continuity errors : sum local = 1e-06, global = 1e-9, cumulative = 1e-9
DILUPBiCGStab:  Solving for p, Initial residual = 0.1, Final residual = 1e-08, No Iterations 45
time step continuity errors : sum local = 2e-09, global = 1e-12, cumulative = 1e-9
ExecutionTime = 1.5 s  ClockTime = 2 s

Time = 2e-05

DILUPBiCGStab:  Solving for p, Initial residual = 1, Final residual = 0.009, No Iterations 20
time step continuity errors : sum local = 3e-09, global = 1e-12, cumulative = 1e-9
ExecutionTime = 2.25 s  ClockTime = 3 s
"""


def test_solver_log_per_step(tmp_path):
    case = tmp_path / "case"
    case.mkdir()
    (case / "log.overPimpleDyMFoam").write_text(LOG)
    rows = solver_log.steps(str(case))
    assert rows.shape == (2, 4)
    assert rows[0].tolist() == [1e-5, 2e-9, 75, 1.5]
    assert rows[1].tolist() == pytest.approx([2e-5, 3e-9, 20, 0.75])


def test_solver_log_restart_replaces_the_steps_from_its_start(tmp_path):
    case = tmp_path / "case"
    case.mkdir()
    (case / "log.overPimpleDyMFoam").write_text(LOG)
    (case / "log.overPimpleDyMFoam.2e-05").write_text(
        LOG.split("Time = 2e-05")[0].replace("Time = 1e-05", "Time = 2e-05"))
    rows = solver_log.steps(str(case))
    assert rows[:, 0].tolist() == [1e-5, 2e-5]
    assert rows[1, 2] == 75 and rows[1, 3] == 1.5


def test_solver_log_step_without_continuity_line_is_nan(tmp_path):
    path = write(tmp_path / "log", "Time = 1\nExecutionTime = 1 s\n")
    assert math.isnan(solver_log.read_log(path)[0][1])


def test_dictionary_with_macros_and_include_read_as_openfoam(tmp_path):
    # what the solver reads: $macros expanded, #include followed (by
    # OpenFOAM's foamDictionary -expand, at 17 digits)
    from flapfoam.io.foam_dict import read_foam_dict
    (tmp_path / "inc").write_text("extra { a 1; }\n")
    d = tmp_path / "dynamicMeshDict"
    d.write_text("FoamFile { version 2.0; format ascii; class dictionary;"
                 " object dynamicMeshDict; }\namp 1.3089969389957472;\n"
                 "coeffs { flapping { amplitude $amp; frequency 20; } }\n"
                 "#include \"inc\"\n")
    r = read_foam_dict(str(d))
    assert r["coeffs"]["flapping"]["amplitude"] == ["1.3089969389957472"]
    assert r["extra"]["a"] == ["1"]
