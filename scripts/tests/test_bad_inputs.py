# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The bad-input runner (flapfoam.checks.bad_inputs): its table read
(rows, variables, refusals), and rows run on a small base folder with
commands of python3: an error exit with the text passes; success, a
missing text, a signal, a hang and a changed folder fail."""

import sys

import pytest

from flapfoam.checks import bad_inputs
from flapfoam.errors import FlapFoamError

PY = sys.executable
# A command that prints the file "value" of its folder and exits 1
SAYS = ("run %s -c \"import sys; print('value ' + open('value').read()."
        "strip() + ': not allowed'); sys.exit(1)\"" % PY)


def table(tmp_path, text):
    path = tmp_path / "badInputs"
    path.write_text(text)
    return str(path)


def base(tmp_path):
    folder = tmp_path / "base"
    folder.mkdir()
    (folder / "value").write_text("good\n")
    return str(folder)


def run(tmp_path, text, *extra):
    argv = [table(tmp_path, text), "-base", base(tmp_path),
            "-dir", str(tmp_path / "runs")] + list(extra)
    return bad_inputs.main(argv)


def test_read_rows_and_variables(tmp_path):
    rows = bad_inputs.read_table(table(tmp_path, """# a comment
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
    assert first.run == ["prog", "-x", "two words"]
    assert (first.exit, first.timeout) == (1, 5.0)
    assert first.expect == [(False, "value 3")]
    assert rows[1].expect == [(True, "^x$")] and rows[1].unchanged == ["runs"]


@pytest.mark.parametrize("text, message", [
    ("badInput a\nrun p\nexpct x\n", "'expct': one of badInput"),
    ("badInput a\nrun p\n", "needs a run line and an expect"),
    ("badInput a\nrun p\nexpect ${nope}\n", "${nope}: no such variable"),
    ("badInput a\nrun p\nexpect x\nbadInput a\nrun p\nexpect x\n",
     "a name not used before"),
    ("badInput a\nedit move f g\nrun p\nexpect x\n", "edit 'move': one of"),
    ("badInput a\nedit set f\nrun p\nexpect x\n", "edit set needs 3 words"),
    ("badInput a\nrun p\nexit -1\nexpect x\n", "'-1': a number >= 0"),
    ("badInput a\nrun p\nexpectRegex (\n", "expectRegex '('"),
    ("run p\n", "before the first badInput"),
    ("# nothing\n", "no badInput row"),
])
def test_table_refused(tmp_path, text, message):
    with pytest.raises(FlapFoamError, match="badInputs line|badInputs:") as e:
        bad_inputs.read_table(table(tmp_path, text), {})
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
    assert bad_inputs.main([path, "-dir", str(tmp_path / "logs")]) == 0
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
