# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.io.flight_data: the checks of a run's file and the comparison of
two runs, on small files made here."""

import h5py
import numpy as np

from flapfoam.io import flight_data as fd
ATTRS = {"case": "c", "level": "tiny", "stencil": "octree", "nRanks": "1",
         "decomposition": "none", "commit": "abc"}


def run(tmp_path, name, q, t=None, attrs=ATTRS):
    """A run folder whose flightData.h5 holds time and joints/q."""
    t = np.arange(len(q))*1e-3 if t is None else t
    h5 = tmp_path / name / "postProcessing" / "flightData" / "0"
    h5.mkdir(parents=True)
    with h5py.File(h5 / "flightData.h5", "w") as f:
        f.create_dataset("time", data=t)
        f.create_dataset("joints/q", data=q)
        f.attrs.update(attrs)
    return str(tmp_path / name)


def lines(capsys):
    return capsys.readouterr().out.splitlines()


def test_check_passes_a_good_file_and_names_what_fails(tmp_path, capsys):
    q = np.column_stack([np.zeros(4), np.linspace(0, 1, 4)])
    case = run(tmp_path, "good", q)
    want = fd.FileChecks(rows=4, attrs={"level": "tiny"}, zero=["joints/q:0"],
                         moving=["joints/q:1"])
    assert fd.check(case, want) == 0
    out = lines(capsys)
    assert len(out) == 7 and all(x.startswith("PASS ") for x in out)
    # wrong rows, a wrong attribute, a column that is not zero
    want = fd.FileChecks(rows=5, attrs={"level": "coarse"},
                         zero=["joints/q:1"])
    assert fd.check(case, want) == 1
    failed = [x for x in lines(capsys) if x.startswith("FAIL ")]
    assert len(failed) == 3
    assert "4 rows (expected 5)" in failed[0]
    assert "(wrong: level)" in failed[1]


def test_check_time_step_and_killed_log(tmp_path, capsys):
    t = np.array([0, 1e-3, 3e-3])
    case = run(tmp_path, "variable", np.zeros((3, 1)), t)
    # an adaptive step passes by default, not as a uniform one
    assert fd.check(case, fd.FileChecks(uniform_step=True)) == 1
    assert fd.check(case, fd.FileChecks()) == 0
    log = tmp_path / "log"
    log.write_text("Time = 0.001\n...\nTime = 0.003\n...\nTime = 0.004\n")
    assert fd.check(case, fd.FileChecks(log=str(log))) == 0
    log.write_text("Time = 0.002\nTime = 0.003\n")
    assert fd.check(case, fd.FileChecks(log=str(log))) == 1
    assert "missing [0.002]" in lines(capsys)[-1]


def test_compare_relative_per_column(tmp_path, capsys):
    q = np.column_stack([np.linspace(1, 2, 5), np.linspace(0, 1e-3, 5)])
    ref = run(tmp_path, "ref", q)
    other = q.copy()
    other[:, 1] *= 1 + 1e-7               # 1e-7 of its own column
    case = run(tmp_path, "case", other)
    assert fd.compare(ref, case, fd.Tolerances(tol=2e-7)) == 0
    assert "max relative difference 1.00e-07" in lines(capsys)[-1]
    assert fd.compare(ref, case, fd.Tolerances(tol=5e-8)) == 1
    shifted = run(tmp_path, "shifted", q, np.arange(5)*1e-3 + 1e-12)
    assert fd.compare(ref, shifted, fd.Tolerances()) == 1
    assert fd.compare(ref, shifted, fd.Tolerances(time_tol=1e-11)) == 0


def test_command_line(tmp_path, capsys):
    q = np.column_stack([np.zeros(4), np.linspace(0, 1, 4)])
    case = run(tmp_path, "good", q)
    assert fd.main(["check", case, "-rows", "4", "-attr", "level=tiny",
                    "-zero", "joints/q:0", "-moving", "joints/q:1"]) == 0
    assert fd.main(["check", case, "-attr", "stencil=walk"]) == 1
    assert fd.main(["compare", case, case, "-datasets", "joints/q"]) == 0
    assert "per dataset: joints/q 0.0e+00" in lines(capsys)[-1]


def test_model_label_names_the_coefficients_that_flew():
    coeffs = {"aerodynamics": {"wing": {"type": ["quasiSteady"],
                                        "CL": ["1.6572591"],
                                        "CD0": ["0.12519382"],
                                        "CD1": ["1.5056736"]}}}
    assert fd.model_label({"model": "quasiSteady"}, coeffs) == \
        "QS: CL 1.657, CD0 0.1252, CD1 1.506"
    assert fd.model_label({"model": "cfd"}, coeffs) == "CFD"
    assert fd.model_label({}, coeffs) == "CFD"
