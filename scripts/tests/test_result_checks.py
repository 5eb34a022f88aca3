# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The Alltest scripts' result checks (flapfoam.checks.result_checks) on small
files made here: each passes what it should and fails a perturbed copy."""

import math

import h5py
import numpy as np
import pytest

from flapfoam.studies import integrator_order

from flapfoam.checks import result_checks as rc
def flight_case(tmp_path, rows=4, joints=2):
    """A run folder: flightData.h5 (time, joints/q, resizable) and the
    joints.dat of the same motion (time, q qDot qDdot of each joint)."""
    t = np.linspace(0, 1e-3, rows)
    q = np.column_stack([np.sin(t*(k + 1)) for k in range(joints)])
    h5 = tmp_path / "postProcessing" / "flightData" / "0" / "flightData.h5"
    h5.parent.mkdir(parents=True)
    with h5py.File(h5, "w") as f:
        f.create_dataset("time", data=t, maxshape=(None,))
        f.create_dataset("joints/q", data=q, maxshape=(None, joints))
    cols = [t]
    for k in range(joints):
        cols += [q[:, k], 0*t, 0*t]
    dat = tmp_path / "postProcessing" / "rigidBodySimulate" / "0"
    dat.mkdir(parents=True)
    save_joints(dat / "joints.dat", np.column_stack(cols), "%.15g")
    return str(tmp_path), str(h5), dat / "joints.dat"


def save_joints(path, rows, fmt):
    """rows as rigidBodySimulate's joints.dat: the header, then the rows
    (time, q_i qDot_i qDdot_i of each joint)."""
    n = (np.shape(rows)[1] - 1)//3
    np.savetxt(path, rows, fmt=fmt, comments="# ", header="time " + " ".join(
        "q_%d qDot_%d qDdot_%d" % (k, k, k) for k in range(n)))


def test_flight_data_joints_equal_and_perturbed(tmp_path):
    case, _, dat = flight_case(tmp_path)
    ok, text = rc.flight_data_joints(case)
    assert ok, text
    assert "4 rows" in text
    # the free joints named by index: their order is the case's
    assert "final q_0..q_1 = " in text and "x = " not in text
    d = np.loadtxt(dat)
    d[-1, 1] += 1e-12
    save_joints(dat, d, "%.15g")
    assert not rc.flight_data_joints(case)[0]


def test_references_match_themselves_not_a_perturbation(tmp_path):
    times, angles = integrator_order.reference(
        integrator_order.SYSTEMS["doublePendulum"])
    path = tmp_path / "ref.dat"
    table = np.column_stack([times, angles])
    np.savetxt(path, table, fmt="%.17g")
    assert rc.references(str(path))[0]
    table[5, 2] += 1e-9
    np.savetxt(path, table, fmt="%.17g")
    ok, text = rc.references(str(path))
    assert not ok and "1e-09" in text


def test_authors_pd_law_by_hand():
    out = rc.authors_pd_law(0.01, 0.0, 0.0, (0.0, 0.0, 0.0))
    # u = 0.2 on [1.2, 1.7]; x, pitch 0: the middles of their ranges
    assert out["flapping.amplitude"] == pytest.approx(
        (math.tanh(0.2) + 1)/2*0.5 + 1.2, abs=1e-15)
    assert out["stroke.offset"] == pytest.approx(0, abs=1e-15)
    assert out["flapping.offset"] == pytest.approx(0, abs=1e-15)


def test_authors_controller_of_a_log(tmp_path):
    dat = tmp_path / "postProcessing" / "rigidBodySimulate" / "0"
    dat.mkdir(parents=True)
    row = [0.05, 0.02, 0.1, 0, 0.03, -0.2, 0, 0.1, 0.5, 0]
    save_joints(dat / "joints.dat", [row], "%.17g")
    want = rc.authors_pd_law(0.02, 0.03, 0.1, (0.1, -0.2, 0.5))
    entries = ", ".join("%s = %.17g" % kv for kv in want.items())
    log = tmp_path / "log"
    log.write_text("PID controller update 1 at t = 0.05: %s\n" % entries)
    assert rc.authors_controller(str(tmp_path))[0]
    log.write_text("PID controller update 1 at t = 0.05: %s\n"
                   % entries.replace("flapping.offset", "flapping.other"))
    assert not rc.authors_controller(str(tmp_path))[0]
    log.write_text("no update\n")
    assert rc.authors_controller(str(tmp_path)) == (
        False, "no controller update in %s/log" % tmp_path)


ENTRY = """wing
{
    type        quasiSteady;
    CL          %s;
    CD0         0.25;
    CD1         2.3;
}
"""


def test_qs_entry_tolerance_and_fit(tmp_path):
    entry, log = tmp_path / "entry", tmp_path / "log"
    entry.write_text(ENTRY % "1.7000001")
    assert rc.qs_entry(str(entry), tol=1e-6)[0]
    assert not rc.qs_entry(str(entry), tol=1e-8)[0]
    log.write_text("QS fitted: x R^2 1, z R^2 0.99999999999999989,\n")
    ok, text = rc.qs_entry(str(entry), str(log))
    assert ok and "R^2 1.0 0.9999999999999999" in text
    log.write_text("QS fitted: x R^2 0.999, z R^2 1,\n")
    assert not rc.qs_entry(str(entry), str(log))[0]


def test_qs_reference_relative_to_range(tmp_path):
    t = np.linspace(0, 1, 11)
    ref = np.column_stack([t, 2*t, 4*t, 0*t, 0*t])   # t x z xDot zDot
    run = np.column_stack([t, 4*t, 0*t, 0*t, 2*t, 0*t, 0*t])
    run[5, 1] += 3e-3          # z: 3e-3 of its range 4
    np.savetxt(tmp_path / "ref", ref)
    np.savetxt(tmp_path / "run", run)
    ok, text = rc.qs_reference(str(tmp_path / "ref"), str(tmp_path / "run"))
    assert ok and "z: max |run - reference| = 0.00075" in text
    run[5, 4] += 4e-3          # x: 2e-3 of its range 2
    np.savetxt(tmp_path / "run", run)
    assert not rc.qs_reference(str(tmp_path / "ref"),
                               str(tmp_path / "run"))[0]


def test_finite_rows(tmp_path):
    p = tmp_path / "t"
    np.savetxt(p, np.ones((3, 2)))
    assert rc.finite_rows(str(p), 3)[0]
    assert not rc.finite_rows(str(p), 4)[0]
    np.savetxt(p, [[1, np.nan], [1, 1], [1, 1]])
    assert not rc.finite_rows(str(p), 3)[0]


def table(path, names, rows):
    path.write_text(",".join(names) + "\n" + "\n".join(
        ",".join(v if isinstance(v, str) else repr(v) for v in r)
        for r in rows) + "\n")
    return str(path)


def test_sweep_table_trends(tmp_path):
    names = ["flapAmplitude", "pitchAmplitude", "meanClimbRate", "meanPower"]
    rows = [[1.2, 0.6, 0.1, 1.0], [1.2, 0.8, 0.2, 1.1],
            [2.0, 0.6, 0.3, 2.0], [2.0, 0.8, 0.4, 2.2]]
    assert rc.sweep_table(table(tmp_path / "s.csv", names, rows))[0]
    rows[3][2] = 0.15          # more stroke, less climb: refused
    assert not rc.sweep_table(table(tmp_path / "s.csv", names, rows))[0]
    assert not rc.sweep_table(table(tmp_path / "s.csv", names, rows[:3]))[0]


def test_hover_table(tmp_path):
    names = ["flapAmplitude", "meanClimbAcceleration", "meanClimbRate"]
    assert rc.hover_table(table(tmp_path / "h.csv", names,
                                [[1.3, 5e-5, 1e-3]]))[0]
    assert not rc.hover_table(table(tmp_path / "h.csv", names,
                                    [[1.3, 2e-4, 1e-3]]))[0]
    assert not rc.hover_table(table(tmp_path / "h.csv", names,
                                    [[1.6, 0, 0]]))[0]


def test_half_row_read_as_whole_rows_and_summarised(tmp_path):
    case, h5, _ = flight_case(tmp_path, rows=3)
    assert rc.flight_data_times(h5) == "0 0.0005 0.001"
    assert rc.rows_summary(h5) == "0 0.0005 0.001 | [3] 0"
    # joints/q one row longer: loaded as 3 rows, the file holds 2 x 999
    assert rc.half_row(case) == "1 3"
    assert rc.rows_summary(h5) == "0 0.0005 0.001 | [3, 4] 2"


def test_hold_open_counts_rows(tmp_path):
    _, h5, _ = flight_case(tmp_path, rows=5)
    assert rc.hold_open(h5, 0.01) == 5


def test_main_prints_and_exits(tmp_path, capsys):
    p = tmp_path / "t"
    np.savetxt(p, np.ones((2, 2)))
    assert rc.main(["finite-rows", str(p), "2"]) == 0
    assert capsys.readouterr().out.startswith("PASS 2 rows")
    assert rc.main(["finite-rows", str(p), "3"]) == 1
    assert capsys.readouterr().out.startswith("FAIL 2 rows (expected 3)")


class FakeTerm:
    def __init__(self, label):
        self.label = label


class FakeRun:
    """What control_errors and control_convergence read of a
    control_plot.Run: made-up rows of one controlled quantity."""
    runs = {}

    def __init__(self, case):
        self.__dict__.update(FakeRun.runs[case])


def fake_runs(monkeypatch, **runs):
    from flapfoam.plots import control as control_plot
    FakeRun.runs = runs
    monkeypatch.setattr(control_plot, "Run", FakeRun)


def test_control_errors_at_updates(monkeypatch):
    err = np.linspace(0, 1, 9)
    # the controller updates at rows 3 and 6, with the rows 2 and 5 errors
    column = np.array([0, 0, 0, err[2], err[2], err[2], err[5], err[5],
                       err[5]])
    run = {"terms": [FakeTerm("height.z")], "errors": {"height.z": err},
           "control": {"height.z.error": column}}
    fake_runs(monkeypatch, a=run)
    ok, text = rc.control_errors("a", 2)
    assert ok and text == "height.z: 2 updates, max difference 0.00e+00"
    assert not rc.control_errors("a", 3)[0]
    run["control"] = {"height.z.error": column + 1e-9*(column != 0)}
    assert not rc.control_errors("a", 2)[0]


def test_control_convergence_tolerances(monkeypatch):
    t = np.linspace(0, 0.25, 51)
    fine = {"t": t, "measures": {"height.z": np.sin(t)}}
    coarse = {"t": t[::5], "measures": {"height.z": np.sin(t[::5]) + 9e-5}}
    fake_runs(monkeypatch, fine=fine, coarse=coarse)
    ok, text = rc.control_convergence("fine", "coarse")
    assert ok and text == "height.z 9e-05 (tol 0.0001)"
    coarse["measures"]["height.z"] += 2e-5
    assert not rc.control_convergence("fine", "coarse")[0]


def test_gain_sweep_table(tmp_path):
    names = ["status"] + [q + ".maxAbsError" for q in rc.CONTROL_TOLERANCE]
    rows = [["ok", 0.1, 0.2, 0.3]]*4
    assert rc.gain_sweep_table(table(tmp_path / "g.csv", names, rows))[0]
    rows = rows[:3] + [["failed", 0.1, 0.2, 0.3]]
    assert not rc.gain_sweep_table(table(tmp_path / "g.csv", names, rows))[0]
