# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The scenario runner (flapfoam.harness.scenarios): its table read
(rows, variables, refusals), and rows run on a small base folder with
commands of python3.  A bad input: an error exit with the text passes;
success, a missing text, a signal, a hang and a changed folder fail.  A
scenario: runs in order, a failed run stops the row; its checks (a
command's lines, files byte for byte, a reference with its tolerance)."""

import sys

import pytest

from flapfoam.harness import scenarios
from flapfoam.harness.scenario_table import read_table
from flapfoam.errors import FlapFoamError

PY = sys.executable
# A command that prints the file "value" of its folder and exits 1
SAYS = ("run %s -c \"import sys; print('value ' + open('value').read()."
        "strip() + ': not allowed'); sys.exit(1)\"" % PY)


def table(tmp_path, text):
    path = tmp_path / "badInputs"
    path.write_text(text)
    return str(path)


def base(tmp_path, value="good"):
    folder = tmp_path / "base"
    folder.mkdir(exist_ok=True)
    (folder / "value").write_text(value + "\n")
    return str(folder)


def run(tmp_path, text, *extra, value="good"):
    argv = [table(tmp_path, text), "-base", base(tmp_path, value),
            "-dir", str(tmp_path / "runs")] + list(extra)
    return scenarios.main(argv)


def test_read_rows_and_variables(tmp_path):
    rows = read_table(table(tmp_path, """# a comment
badInput first
edit sed value s/good/${bad}/
edit write other a\\nb
run prog -x 'two words'
exit 1
expect value ${bad}
timeout 5

badInput second
run prog
expectRegex ^x$
unchanged runs
"""), {"bad": "3"})
    assert [r.name for r in rows] == ["first", "second"]
    first = rows[0]
    assert first.edits == [["sed", "value", "s/good/3/"],
                           ["write", "other", "a\\nb"]]
    assert first.runs == [["prog", "-x", "two words"]]
    assert (first.exit, first.timeout) == (1, 5.0)
    assert first.expect == [(False, "value 3")]
    assert rows[1].expect == [(True, "^x$")] and rows[1].unchanged == ["runs"]


@pytest.mark.parametrize("text, message", [
    ("badInput a\nrun p\nexpct x\n", "'expct' in badInput a: one of"),
    ("badInput a\nrun p\n", "needs one run line and an expect"),
    ("badInput a\nrun p\nrun q\nexpect x\n", "needs one run line"),
    ("badInput a\nrun p\ncheck q\nexpect x\n", "'check' in badInput a"),
    ("scenario a\nexit 1\n", "'exit' in scenario a"),
    ("scenario a\nexpect x\n", "scenario a needs a run line"),
    ("scenario a\nrun p\nsame x y\n", "same needs at least 3 words"),
    ("badInput a\nrun p\nexpect ${nope}\n", "${nope}: no such variable"),
    ("badInput a\nrun p\nexpect x\nbadInput a\nrun p\nexpect x\n",
     "a name not used before"),
    ("badInput a\nedit move f g\nrun p\nexpect x\n", "edit 'move': one of"),
    ("badInput a\nedit set f\nrun p\nexpect x\n", "edit set needs 3 words"),
    ("badInput a\nrun p\nexit -1\nexpect x\n", "'-1': a number >= 0"),
    ("badInput a\nrun p\nexpectRegex (\n", "expectRegex '('"),
    ("run p\n", "before the first badInput or scenario"),
    ("# nothing\n", "no badInput or scenario row"),
])
def test_table_refused(tmp_path, text, message):
    with pytest.raises(FlapFoamError, match="badInputs line|badInputs:") as e:
        read_table(table(tmp_path, text), {})
    assert message in str(e.value)


def test_row_passes_and_its_copy_goes(tmp_path, capsys):
    text = "badInput bad value\nedit sed value s/good/-1/\n%s\nexit 1\n" \
           "expect value -1: not allowed\nexpectRegex ^value -1:\n" % SAYS
    assert run(tmp_path, text) == 0
    out = capsys.readouterr().out
    assert out.startswith("PASS bad input bad value (exit 1)")
    assert not (tmp_path / "runs" / "bad_value").exists()
    assert (tmp_path / "base" / "value").read_text() == "good\n"


@pytest.mark.parametrize("command, expect, problem", [
    ("run %s -c \"print('value x')\"" % PY, "value", "not an error exit"),
    (SAYS, "value -2", "output lacks [value -2]"),
    ("run %s -c \"import os, signal; os.kill(os.getpid(), signal.SIGKILL)\""
     % PY, "x", "not an error exit"),
    ("run %s -c \"import time; time.sleep(5)\"\ntimeout 0.5" % PY, "x",
     "a hang"),
    ("run %s -c \"open('made', 'w'); raise SystemExit(1)\"\nunchanged ." % PY,
     "", "./ changed"),
    ("run no-such-program-here", "x", "output lacks [x]"),
])
def test_row_fails(tmp_path, capsys, command, expect, problem):
    text = "badInput b\n%s\nexpect %s\n" % (command, expect) if expect \
        else "badInput b\n%s\nexpectRegex .*\n" % command
    assert run(tmp_path, text) == 1
    out = capsys.readouterr().out
    assert out.startswith("FAIL bad input b:") and problem in out
    assert (tmp_path / "runs" / "b" / "log").is_file()


def test_exit_code_exact(tmp_path, capsys):
    text = "badInput b\n%s\nexit 2\nexpect value good\n" % SAYS
    assert run(tmp_path, text) == 1
    assert "exit 1, not 2" in capsys.readouterr().out


def test_edit_that_fails_is_a_failure(tmp_path, capsys):
    text = "badInput b\nedit delete missing\n%s\nexpect x\n" % SAYS
    assert run(tmp_path, text) == 1
    assert capsys.readouterr().out.startswith("FAIL bad input b: ")


def test_without_base_runs_here(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "value").write_text("here\n")
    path = table(tmp_path, "badInput b\n%s\nexpect value here\n" % SAYS)
    assert scenarios.main([path, "-dir", str(tmp_path / "logs")]) == 0
    assert (tmp_path / "logs" / "log.b").read_text().startswith("value here")


@pytest.mark.parametrize("extra, message", [
    (["-var", "x"], "-var 'x': NAME=VALUE"),
    (["-only", "nope"], "-only 'nope': no such row"),
])
def test_options_refused(tmp_path, extra, message):
    with pytest.raises(FlapFoamError, match=message):
        run(tmp_path, "badInput b\n%s\nexpect x\n" % SAYS, *extra)


def test_case_is_the_rows_folder(tmp_path, capsys):
    text = ("badInput c\nrun %s -c \"import sys; sys.exit(sys.argv[1])\" "
            "${case}\nexpect ${case}\n" % PY)
    assert run(tmp_path, text) == 0
    assert str(tmp_path / "runs" / "c") in capsys.readouterr().out


# A command that writes joints.dat (q_0 at t = 1: the folder's value) in
# its folder and says PASS
WRITES = ("run %s -c \"import os; d = 'postProcessing/eABAMeshMotion/0'; "
          "os.makedirs(d, exist_ok=True); open(d + '/joints.dat', 'w')."
          "write('# time q_0\\\\n0 0\\\\n1 ' + open('value').read().strip() "
          "+ '\\\\n'); print('PASS wrote')\"" % PY)


def reference(tmp_path, q1, tolerance="1e-6"):
    folder = tmp_path / "ref"
    (folder / "postProcessing" / "eABAMeshMotion" / "0").mkdir(parents=True)
    (folder / "postProcessing/eABAMeshMotion/0/joints.dat").write_text(
        "# time q_0\n0 0\n1 %s\n" % q1)
    (folder / "reference").write_text("# why\ntolerance %s\nrows all\n"
                                      % tolerance)
    return str(folder)


def scenario_lines(tmp_path, capsys, q1, rows):
    """(exit status, output lines, reference folder) of a scenario that
    writes q_0 = 2.0 at t = 1, then rows (%s: the reference folder, whose
    q_0 at t = 1 is q1)."""
    ref = reference(tmp_path, q1)
    rc = run(tmp_path, "scenario s\n%s\n%s" % (WRITES, rows % ref),
             value="2.0")
    return rc, capsys.readouterr().out.splitlines(), ref


def test_scenario_runs_in_order_then_checks(tmp_path, capsys):
    rc, out, ref = scenario_lines(tmp_path, capsys, "2.0000001", (
        "run %s -c \"print('second')\"\nexpect second\n"
        "check %s -c \"print('PASS all good')\"\n"
        "same . . value\nreference . %%s\n" % (PY, PY)))
    assert rc == 0
    assert out[0].startswith("PASS [s] run 1 of 2: ") and \
        out[0].endswith("1 PASS lines of its own)")
    assert out[1].startswith("PASS [s] run 2 of 2: ")
    assert out[2] == "PASS [s] the output: second"
    assert out[3] == "PASS [s] all good"
    assert out[4] == "PASS [s] . and . byte for byte: value"
    assert out[5].startswith("PASS [s] . against %s: joints.dat all rows (2)"
                             % ref)
    assert (tmp_path / "runs" / "s" / "log.2").read_text() == "second\n"


def test_scenario_failures(tmp_path, capsys):
    rc, out, ref = scenario_lines(tmp_path, capsys, "2.1", (
        "check %s -c \"raise SystemExit(3)\"\n"
        "check %s -c \"print('FAIL not good')\"\n"
        "same . ../ref value\nreference . %%s\n" % (PY, PY)))
    assert rc == 1
    assert out[0].startswith("PASS [s] ")
    assert out[1].startswith("FAIL [s] %s -c raise SystemExit(3): exit 3"
                             % PY)
    assert out[2] == "FAIL [s] not good"
    assert out[3] == "FAIL [s] . and ../ref byte for byte: differ or " \
        "missing: value"
    assert out[4].startswith("FAIL [s] . against %s: joints.dat all rows "
                             "(2): max relative difference 4.76e-02 "
                             "(tol 1e-06)" % ref)


def test_failed_run_stops_the_scenario(tmp_path, capsys):
    text = ("scenario s\nrun %s -c \"print('FAIL inner')\"\n"
            "run %s -c \"open('second', 'w')\"\ncheck false\n" % (PY, PY))
    assert run(tmp_path, text) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "FAIL [s] inner"
    assert out[1].startswith("FAIL [s] run 1 of 2: ") and \
        "exit 0, 1 FAIL lines of its own" in out[1]
    assert len(out) == 2 and not (tmp_path / "runs" / "s" / "second").exists()


def test_update_references(tmp_path, capsys):
    value = "3.5"
    ref = reference(tmp_path, "1")
    text = "scenario s\n%s\nreference . %s\n" % (WRITES, ref)
    assert run(tmp_path, text, "-updateReferences", value=value) == 0
    assert run(tmp_path, text, value=value) == 0
    assert "1 3.5" in open(ref + "/postProcessing/eABAMeshMotion/0/"
                           "joints.dat").read()


@pytest.mark.parametrize("text, message", [
    ("rows all\n", "needs 'tolerance X'"),
    ("tolerance 1e-6\nrows some\n", "needs 'tolerance X'"),
    ("tolerance 1e-6\ntol 2\n", "line 2: 'tol 2': one of"),
])
def test_reference_file_refused(tmp_path, capsys, text, message):
    value = "1"
    ref = reference(tmp_path, "1")
    (tmp_path / "ref" / "reference").write_text(text)
    text = "scenario s\n%s\nreference . %s\n" % (WRITES, ref)
    assert run(tmp_path, text, value=value) == 1
    assert message in capsys.readouterr().out
