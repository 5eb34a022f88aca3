# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.paths: the project's folder from FLAPFOAM_PROJECT_DIR, else the
tree the package sits in (the portable archive)."""

import os

from flapfoam import paths

TREE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def test_the_environment_first(monkeypatch, tmp_path):
    monkeypatch.setenv("FLAPFOAM_PROJECT_DIR", str(tmp_path))
    assert paths.project_dir() == str(tmp_path)
    assert paths.project_path("bench", "scaling") == \
        os.path.join(str(tmp_path), "bench", "scaling")


def test_else_the_tree_of_the_package(monkeypatch):
    monkeypatch.delenv("FLAPFOAM_PROJECT_DIR", raising=False)
    assert paths.project_dir() == TREE
    assert os.path.isfile(paths.project_path("bin", "tools", "droneAllrun"))
