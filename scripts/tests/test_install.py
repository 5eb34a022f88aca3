# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The package as pip installs it (scripts/README.md): a wheel built from
scripts/pyproject.toml holds every subpackage and module, and the flapfoam
command of a venv it is installed into (not editable, PYTHONPATH unset)
lists the tools and runs one.  Offline: the venv sees Debian's numpy and
scipy (--system-site-packages), pip builds with the setuptools it has."""

import math
import os
import shutil
import subprocess
import sys
import zipfile

import pytest

from flapfoam import __main__ as command

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
PACKAGE = os.path.join(SCRIPTS, "flapfoam")


def run(args, **kw):
    out = subprocess.run(args, capture_output=True, text=True, **kw)
    assert out.returncode == 0, "%s\n%s%s" % (args, out.stdout, out.stderr)
    return out.stdout


def source_modules():
    """The package's modules, as paths in a wheel (flapfoam/io/tables.py)."""
    found = set()
    for folder, dirs, files in os.walk(PACKAGE):
        dirs[:] = [d for d in dirs if d != "__pycache__"]
        rel = os.path.relpath(folder, SCRIPTS)
        found |= {"%s/%s" % (rel, f) for f in files if f.endswith(".py")}
    return found


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """(wheel, venv, env): the wheel built from a copy of scripts/ (so that
    no build folder lands in the tree), installed into a fresh venv."""
    tmp = tmp_path_factory.mktemp("install")
    src = tmp / "src"
    shutil.copytree(PACKAGE, src / "flapfoam",
                    ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(os.path.join(SCRIPTS, "pyproject.toml"), src)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-index",
         "--no-build-isolation", "-q", "-w", str(tmp / "dist"), str(src)],
        env=env, cwd=tmp)
    wheel, = (tmp / "dist").glob("flapfoam-*.whl")
    venv = tmp / "venv"
    run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)],
        env=env, cwd=tmp)
    run([str(venv / "bin" / "python"), "-m", "pip", "install", "--no-deps",
         "--no-index", "-q", str(wheel)], env=env, cwd=tmp)
    return wheel, venv, env


def test_the_wheel_holds_every_module(installed):
    wheel = installed[0]
    with zipfile.ZipFile(wheel) as zf:
        held = {n for n in zf.namelist() if n.endswith(".py")}
    expected = source_modules()
    subpackages = {os.path.dirname(m) for m in expected} - {"flapfoam"}
    assert len(subpackages) >= 9     # io, models, ..., harness
    assert "flapfoam/harness/__init__.py" in held
    assert held == expected, sorted(expected ^ held)


def test_the_installed_command_lists_and_runs_the_tools(installed):
    _, venv, env = installed
    flapfoam = str(venv / "bin" / "flapfoam")
    where = run([str(venv / "bin" / "python"), "-c",
                 "import flapfoam; print(flapfoam.__file__)"],
                env=env, cwd=venv)
    assert where.startswith(str(venv)), where
    listed = {line.split()[0] for line in
              run([flapfoam, "-help"], env=env, cwd=venv).splitlines()
              if line.startswith("  ")}
    assert listed == set(command.tools())
    usage = run([flapfoam, "check_run", "-h"], env=env, cwd=venv)
    assert usage.startswith("usage: flapfoam check_run")
    # a tool that imports numpy: the planform area of the paper's wing,
    # its mean chord times its span, 0.015 m x 0.05 m
    rows = dict(line.split() for line in
                run([flapfoam, "wing_geometry"], env=env,
                    cwd=venv).splitlines())
    assert math.isclose(float(rows["planformArea"]), 7.5e-4, rel_tol=1e-9)
