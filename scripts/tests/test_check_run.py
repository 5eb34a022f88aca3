# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The drone runs' checks (flapfoam check_run) on small run folders made
here: each check passes what it should and fails a table made to fail it;
the step timers' verdicts hold no timing (a run on a loaded machine, with
its rows far from adding up, passes while its identities hold)."""

import math

import numpy as np
import pytest

from flapfoam.checks import check_run as cr
from flapfoam.models.wang import wang_motion

WANG = {"type": ["wang"], "waveform": ["flapping"], "amplitude": ["1.2"],
        "frequency": ["20"], "K": ["0.7"]}
MESH_DICT = """FoamFile { format ascii; class dictionary; object dynamicMeshDict; }
eABAMeshMotionCoeffs
{
    imposedMotion
    {
        flapping { type wang; joint 1; waveform flapping; amplitude 1.2;
                   frequency 20; K 0.7; }
    }
}
"""
TIMES = np.linspace(0, 4e-4, 5)


def wang_columns(t):
    """q, qDot, qDdot of joint 1 (the flapping entry) at times t."""
    return wang_motion(WANG)(t)


def joints_rows(times, shift=0.0):
    """joints.dat rows: joint 0 free (a made-up motion), joint 1 Wang's."""
    q1, qd1, qdd1 = wang_columns(times)
    return np.column_stack([times, 1e-3*times + shift, 1e-3 + 0*times,
                            0*times, q1, qd1, qdd1])


def write_joints(case, rows, name="eABAMeshMotion", start="0"):
    folder = case / "postProcessing" / name / start
    folder.mkdir(parents=True, exist_ok=True)
    np.savetxt(folder / "joints.dat", rows, fmt="%.12g", header=(
        "time q_0 qDot_0 qDdot_0 q_1 qDot_1 qDdot_1"), comments="# ")


def write_state(case, t, q, q_dot, q_ddot):
    folder = case / ("%g" % t) / "uniform"
    folder.mkdir(parents=True, exist_ok=True)
    vec = lambda v: "%d(%s)" % (len(v), " ".join("%.17g" % x for x in v))
    (folder / "rigidBodyMotionState").write_text(
        "q %s;\nqDot %s;\nqDdot %s;\nt %.17g;\n"
        % (vec(q), vec(q_dot), vec(q_ddot), t))


def drone_run(tmp_path, name="run", shift=0.0):
    """A run folder: the multibody dictionary, joints.dat of 5 steps and
    the state of the last one."""
    case = tmp_path / name
    (case / "constant").mkdir(parents=True)
    (case / "constant" / "dynamicMeshDict").write_text(MESH_DICT)
    rows = joints_rows(TIMES, shift)
    write_joints(case, rows)
    last = rows[-1]
    write_state(case, last[0], last[[1, 4]], last[[2, 5]], last[[3, 6]])
    return case


def verdicts(capsys, names):
    """The PASS/FAIL lines printed since the last call whose text starts
    with one of names: {name: passed}."""
    out = {}
    for line in capsys.readouterr().out.splitlines():
        word, rest = line.split(" ", 1)
        for name in names:
            if rest.startswith(name + " "):
                out[name] = word == "PASS"
    return out


# ----------------------------------------------------------- prescribed

PRESCRIBED = ["prescribed state files", "prescribed joints.dat"]


def test_prescribed_exact_passes_and_a_perturbed_table_fails(tmp_path,
                                                             capsys):
    case = drone_run(tmp_path)
    assert cr.check_prescribed(str(case), None, 1e-12, 1e-11) == 0
    assert verdicts(capsys, PRESCRIBED) == {n: True for n in PRESCRIBED}
    rows = joints_rows(TIMES)
    rows[2, 4] += 1e-9*1.2          # q_1 off by 1e-9 of the amplitude
    write_joints(case, rows)
    assert cr.check_prescribed(str(case), None, 1e-12, 1e-11) == 1
    assert verdicts(capsys, PRESCRIBED) == {PRESCRIBED[0]: True,
                                            PRESCRIBED[1]: False}


def test_prescribed_a_perturbed_state_file_fails(tmp_path, capsys):
    case = drone_run(tmp_path)
    t = TIMES[-1]
    q1, qd1, qdd1 = wang_columns(t)
    write_state(case, t, [0, q1], [0, qd1], [0, qdd1*(1 + 1e-9)])
    assert cr.check_prescribed(str(case), None, 1e-12, 1e-11) == 1
    assert verdicts(capsys, PRESCRIBED) == {PRESCRIBED[0]: False,
                                            PRESCRIBED[1]: True}


def test_prescribed_without_imposed_motion_fails(tmp_path):
    case = drone_run(tmp_path)
    (case / "constant" / "dynamicMeshDict").write_text(
        "eABAMeshMotionCoeffs { }\n")
    assert cr.check_prescribed(str(case), None, 1e-12, 1e-11) == 1


# --------------------------------------------------------------- timers

COLUMNS = ["time", "rbd", "overset", "pimple", "total", "preUpdate",
           "oversetMovePoints", "pimpleMomentum", "pimplePressure",
           "pimpleTurbulence", "pimplePressureSolve", "pimpleMomentumSolve",
           "pimpleOtherSolve", "pimpleOversetInterpolate", "pimpleSync",
           "pimpleInterpolations", "pIterations1"]


def timer_row(t, rest=0.0, sync=0.0):
    """One rank's step: parts adding up to pimple; rest: seconds of the
    step in no timer (what a loaded machine puts between two timers)."""
    pimple = 0.010 + 0.002 + 0.003 + 0.020 + 0.001 + 0.0005 + 0.001 + sync
    row = {"time": t, "rbd": 0.0004, "overset": 0.003,
           "oversetMovePoints": 0.003, "pimpleMomentum": 0.010,
           "pimplePressure": 0.002, "pimpleTurbulence": 0.003,
           "pimplePressureSolve": 0.020, "pimpleMomentumSolve": 0.001,
           "pimpleOtherSolve": 0.0005, "pimpleOversetInterpolate": 0.001,
           "pimpleSync": sync, "pimple": pimple, "preUpdate": 0.0001,
           "pimpleInterpolations": 12, "pIterations1": 7}
    row["total"] = row["rbd"] + row["overset"] + pimple \
        + row["preUpdate"] + 1e-5 + rest
    return row


def write_timers(case, rows, ranks):
    folder = case / "postProcessing" / "stepTimers" / "0"
    folder.mkdir(parents=True, exist_ok=True)
    cols = [c for c in COLUMNS if c in rows[0]]
    with open(folder / "stepTimers.dat", "w") as fh:
        fh.write("# Step timers\n# time\t%s\n" % "\t".join(cols[1:]))
        for r in rows:
            fh.write("\t".join("%.6g" % r[c] for c in cols) + "\n")
    with open(folder / "stepTimersRanks.dat", "w") as fh:
        fh.write("# Per rank\n# rank\tnSteps\t%s\n" % "\t".join(cols[1:]))
        for k, r in enumerate(ranks):
            fh.write("%d\t8\t%s\n" % (k, "\t".join(
                "%.6e" % r[c] for c in cols[1:])))


def timed_run(tmp_path, rows, ranks):
    case = tmp_path / "timed"
    case.mkdir(exist_ok=True)
    write_timers(case, rows, ranks)
    return str(case)


ALL_TIMERS = ["timers columns", "timers pressure solves",
              "timers pimple split", "timers step cover"]


def timer_verdicts(case, capsys):
    status = cr.check_timers(case, "timers", 2)
    return status, verdicts(capsys, ALL_TIMERS)


def serial_rows(rest=0.0):
    return [timer_row(1e-5*(k + 1), rest*(k % 3)) for k in range(10)]


def test_timers_serial_pass(tmp_path, capsys):
    rows = serial_rows()
    status, v = timer_verdicts(timed_run(tmp_path, rows, rows[:1]), capsys)
    assert status == 0 and v == {n: True for n in ALL_TIMERS}


def test_timers_loaded_machine_passes(tmp_path, capsys):
    """Steps with up to 60 ms untimed (a descheduled rank): the closure is
    off by tens of per cent, reported, and no verdict fails."""
    rows = serial_rows(rest=0.03)
    status, v = timer_verdicts(timed_run(tmp_path, rows, rows[:1]), capsys)
    assert status == 0 and all(v.values())


def test_timers_parallel_checks_the_ranks_not_the_maxima(tmp_path, capsys):
    """The rows are maxima over the ranks (taken from different ranks,
    they need not add up); the ranks' own means must, the faster rank's
    wait in its pimpleSync: the CI failure of stop 44's clean run."""
    fast, slow = timer_row(0, sync=0.004), timer_row(0)
    rows = []
    for k in range(10):
        r = {c: max(fast[c], slow[c]) for c in fast}
        r["time"] = 1e-5*(k + 1)
        r["pimpleMomentum"] *= 1.5        # a maximum from another rank
        rows.append(r)
    status, v = timer_verdicts(timed_run(tmp_path, rows, [fast, slow]),
                               capsys)
    assert status == 0 and all(v.values()), v


@pytest.mark.parametrize("spoil, failed", [
    (lambda r: r.pop("pimpleSync"), "timers columns"),
    (lambda r: r.update(pIterations1=0), "timers pressure solves"),
    (lambda r: r.update(pimplePressure=r["pimplePressure"] + 2e-5),
     "timers pimple split"),
    (lambda r: r.update(rbd=r["rbd"] + 2e-5), "timers step cover"),
])
def test_timers_each_verdict_fails_its_table(tmp_path, capsys, spoil,
                                             failed):
    rows = serial_rows()
    for r in rows[3:] if failed != "timers columns" else rows:
        spoil(r)
    status, v = timer_verdicts(timed_run(tmp_path, rows, rows[:1]), capsys)
    assert status == 1
    assert v[failed] is False
    assert all(ok for name, ok in v.items() if name != failed), v


def test_timers_parallel_a_rank_that_does_not_add_up_fails(tmp_path,
                                                           capsys):
    fast, slow = timer_row(0, sync=0.004), timer_row(0)
    fast["pimpleSync"] = 0.0              # its wait in no part
    rows = [dict(slow, time=1e-5*(k + 1)) for k in range(10)]
    status, v = timer_verdicts(timed_run(tmp_path, rows, [fast, slow]),
                               capsys)
    assert status == 1 and v["timers pimple split"] is False


def test_timers_no_rows_fails(tmp_path, capsys):
    rows = serial_rows()[:2]              # start-up rows only
    assert cr.check_timers(timed_run(tmp_path, rows, rows[:1]), None, 2) == 1


# ---------------------------------------------- compare, initial, rbs

def test_compare_same_passes_and_a_difference_fails(tmp_path):
    a, b = drone_run(tmp_path, "a"), drone_run(tmp_path, "b")
    want = cr.JointsComparison(["q_0", "q_1"], 1e-6, "all", True)
    assert cr.check_compare(str(a), str(b), None, want) == 0
    c = drone_run(tmp_path, "c", shift=1e-8)     # q_0 off by 2e-6 of it
    assert cr.check_compare(str(a), str(c), None, want) == 1
    assert cr.check_compare(str(a), str(c), None, cr.JointsComparison(
        ["q_1"], 1e-6, "all", False)) == 0


def test_compare_last_rows_at_different_times_fails(tmp_path):
    a, b = drone_run(tmp_path, "a"), drone_run(tmp_path, "b")
    write_joints(b, joints_rows(TIMES[:-1]))
    assert cr.check_compare(str(a), str(b), None,
                            cr.JointsComparison()) == 1


def test_compare_a_state_that_differs_fails_alone(tmp_path, capsys):
    a, b = drone_run(tmp_path, "a"), drone_run(tmp_path, "b")
    rows = joints_rows(TIMES)
    last = rows[-1]
    write_state(b, last[0], last[[1, 4]]*(1 + 1e-3), last[[2, 5]],
                last[[3, 6]])
    want = cr.JointsComparison(None, 1e-6, "last", True)
    assert cr.check_compare(str(a), str(b), None, want) == 1
    assert verdicts(capsys, ["compare joints.dat", "compare state"]) == {
        "compare joints.dat": True, "compare state": False}


def test_initial_values_and_signs(tmp_path):
    case = str(drone_run(tmp_path))
    q1 = wang_columns(0.0)[0]
    assert cr.check_initial(case, None, "0:0,1:%.15g" % q1, None, 1e-12) == 0
    assert cr.check_initial(case, None, "1:%.15g" % (q1 + 1e-9), None,
                            1e-12) == 1
    # qDot_0 is +1e-3: the sign -1 fails
    assert cr.check_initial(case, None, "0:0", "0:1", 1e-12) == 0
    assert cr.check_initial(case, None, "0:0", "0:-1", 1e-12) == 1


def test_rbs_same_rows_pass_misaligned_or_perturbed_fail(tmp_path):
    case = drone_run(tmp_path)
    rows = joints_rows(TIMES)
    write_joints(case, rows, "rigidBodySimulate")
    assert cr.check_rbs(str(case), str(case), None, 1e-10) == 0
    rows[1, 5] *= 1 + 1e-8
    write_joints(case, rows, "rigidBodySimulate")
    assert cr.check_rbs(str(case), str(case), None, 1e-10) == 1
    write_joints(case, joints_rows(TIMES[:-1]), "rigidBodySimulate")
    assert cr.check_rbs(str(case), str(case), None, 1e-10) == 1


# ----------------------------------------------------------- dictionary

def test_dictionary_rewritten_numbers_and_changed_keys(tmp_path):
    given = tmp_path / "given"
    given.write_text("a { b 1.3089969389957472; c word; } d 2;\n")
    run = tmp_path / "run"
    run.write_text("a { b 1.3089969389957472; c word; } d 3;\n")
    assert cr.check_dictionary(str(run), str(given), None, ["d"]) == 0
    assert cr.check_dictionary(str(run), str(given), None, []) == 1
    assert cr.check_dictionary(str(run), str(given), None,
                               ["d", "a/missing"]) == 1
    run.write_text("a { b 1.309; c word; } d 3;\n")     # 6 digits
    assert cr.check_dictionary(str(run), str(given), None, ["d"]) == 1


def test_restart_join_keeps_the_later_start(tmp_path):
    """joints() joins the start folders: the later start's rows replace
    the earlier ones from its start time on."""
    case = drone_run(tmp_path)
    later = joints_rows(TIMES[2:], shift=5.0)
    write_joints(case, later, start="%g" % TIMES[2])
    cols, rows = cr.joints(str(case))
    assert len(rows) == len(TIMES)
    assert rows[1, 1] == pytest.approx(1e-3*TIMES[1], abs=1e-15)
    assert rows[2, 1] == pytest.approx(1e-3*TIMES[2] + 5.0, abs=1e-12)
    assert math.isclose(rows[-1, 0], TIMES[-1])
