# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam captured_run on small shell commands: a clean one passes; one
that leaves a process holding its output fails (no end of the pipes) and
one that leaves a process with its output closed fails (left running)."""

from flapfoam.harness import captured_run as cr


def verdicts(capsys):
    return [line.split(" ", 1) for line in
            capsys.readouterr().out.splitlines()]


def test_a_clean_command_passes(capsys):
    assert cr.main(["-expect", "done", "--", "bash", "-c",
                    "echo start; echo done: ok"]) == 0
    assert all(word == "PASS" for word, _ in verdicts(capsys))


def test_a_process_holding_the_output_is_a_hang(capsys):
    # the background sleep inherits stdout: the pipe's end never comes
    assert cr.main(["-timeout", "2", "--", "bash", "-c",
                    "sleep 30 & echo done"]) == 1
    lines = verdicts(capsys)
    assert lines[0][0] == "FAIL" and "no end of its output" in lines[0][1]
    assert lines[-1][0] == "FAIL" and "left" in lines[-1][1]


def test_a_process_left_running_fails(capsys):
    # its output closed: the pipes end, but the process outlives the command
    assert cr.main(["--", "bash", "-c",
                    "sleep 30 > /dev/null 2>&1 & echo done"]) == 1
    lines = verdicts(capsys)
    assert lines[0][0] == "PASS"
    assert lines[-1][0] == "FAIL" and "1 process(es)" in lines[-1][1]


def test_exit_status_and_last_line(capsys):
    assert cr.main(["-expect", "done", "--", "bash", "-c",
                    "echo other; exit 3"]) == 1
    words = [w for w, _ in verdicts(capsys)]
    assert words == ["PASS", "FAIL", "FAIL", "PASS"]
