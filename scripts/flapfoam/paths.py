# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Where the project is: FLAPFOAM_PROJECT_DIR (etc/bashrc), else the tree
this package sits in (scripts/flapfoam/..), as in the portable archive."""

import os


def project_dir():
    """The project's top folder."""
    return os.environ.get("FLAPFOAM_PROJECT_DIR") or os.path.abspath(
        os.path.join(os.path.dirname(__file__), "..", ".."))


def project_path(*parts):
    """A path inside the project: project_path("bench", "scaling")."""
    return os.path.join(project_dir(), *parts)
