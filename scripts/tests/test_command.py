# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""bin/flapfoam and flapfoam.__main__: the one command of the tools, run
with a python3 first on the PATH that has no numpy (a cluster module's,
conda's, pyenv's)."""

import io
import os
import subprocess

import pytest

from flapfoam import __main__ as command
BIN = os.path.join(os.path.dirname(__file__), "..", "..", "bin", "flapfoam")


def broken_python_first(tmp_path):
    """An environment whose first python3 on the PATH lacks numpy, and no
    FLAPFOAM_PYTHON or PYTHONPATH."""
    fake = tmp_path / "python3"
    fake.write_text("#!/bin/sh\necho \"ModuleNotFoundError: No module named"
                    " 'numpy'\" 1>&2\nexit 1\n")
    fake.chmod(0o755)
    env = {k: v for k, v in os.environ.items()
           if k not in ("FLAPFOAM_PYTHON", "PYTHONPATH")}
    env["PATH"] = "%s:%s" % (tmp_path, env.get("PATH", ""))
    return env


def test_tools_are_the_runnable_modules():
    tools = command.tools()
    assert {"flight_data", "ascent", "qs_calibrate"} <= set(tools)
    assert "plotting" not in tools and "checklist" not in tools
    assert tools["flight_data"] == (
        "flapfoam.io.flight_data",
        "Read and check the flight data (HDF5) of a drone run.")
    # a subpackage's TOOL_PREFIX names its tools
    assert tools["scaling_validate"][0] == "flapfoam.scaling.validate"
    assert tools["plot_step_timers"][0] == "flapfoam.plots.step_timers"


def test_help_lists_each_tool_once_under_its_subpackage():
    out = io.StringIO()
    command.usage(out)
    groups, heading = {}, None
    for line in out.getvalue().splitlines()[1:]:
        if line and not line.startswith(" "):
            heading = line.split(":")[0]
            assert heading not in groups, heading
            groups[heading] = []
        elif line:
            groups[heading].append(line.split()[0])
    tools = command.tools()
    listed = [t for names in groups.values() for t in names]
    assert sorted(listed) == sorted(tools)      # each tool once
    for heading, names in groups.items():
        assert names and all(tools[t][0].startswith(
            "flapfoam.%s." % heading) for t in names), (heading, names)
    assert list(groups) == sorted(groups)
    assert set(groups) == {m.split(".")[1] for m, _ in tools.values()}
    assert "scenarios" in groups["harness"] and \
        "check_run" in groups["checks"] and \
        "scaling_validate" in groups["scaling"]
    assert "harness: The test harness\n" in out.getvalue()


def test_two_tools_of_one_name_are_refused(tmp_path, monkeypatch):
    for sub in ("a", "b"):
        (tmp_path / sub).mkdir()
        (tmp_path / sub / "__init__.py").write_text("")
        (tmp_path / sub / "same.py").write_text(
            '"""Same."""\nif __name__ == "__main__":\n    pass\n')
    monkeypatch.setattr(command, "__file__", str(tmp_path / "__main__.py"))
    with pytest.raises(RuntimeError, match="two tools named same"):
        command.tools()


def test_help_and_a_tool_with_a_python3_without_numpy(tmp_path):
    env = broken_python_first(tmp_path)
    out = subprocess.run([BIN, "-help"], env=env, capture_output=True,
                         text=True)
    assert out.returncode == 0, out.stderr
    assert "  flight_data " in out.stdout and "  ascent " in out.stdout
    # a tool that imports numpy and h5py
    run = tmp_path / "run"
    out = subprocess.run([BIN, "flight_data", "check", str(run)], env=env,
                         capture_output=True, text=True)
    assert "No module named" not in out.stderr
    assert out.returncode == 1 and "no postProcessing/flightData" in \
        out.stdout + out.stderr


def test_unknown_tool_is_refused(tmp_path):
    out = subprocess.run([BIN, "flight_dat"], env=broken_python_first(
        tmp_path), capture_output=True, text=True)
    assert out.returncode == 2
    assert "no tool 'flight_dat' (flapfoam -help lists them)" in out.stderr


@pytest.mark.parametrize("tool", sorted(command.tools()))
@pytest.mark.parametrize("option", ["-h", "-help"])
def test_every_tool_answers_help_under_its_name(tool, option, capsys):
    with pytest.raises(SystemExit) as end:
        command.main([tool, option])
    out = capsys.readouterr().out
    assert end.value.code in (0, None), out
    assert out.startswith("usage: flapfoam %s " % tool), out
