# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Where the project is: FLAPFOAM_PROJECT_DIR (etc/bashrc), else the tree
this package sits in (scripts/flapfoam/..), as in the portable archive; a
tool's output folder, made."""

import os

from flapfoam.errors import FlapFoamError


def project_dir():
    """The project's top folder."""
    return os.environ.get("FLAPFOAM_PROJECT_DIR") or os.path.abspath(
        os.path.join(os.path.dirname(__file__), "..", ".."))


def project_path(*parts):
    """A path inside the project: project_path("bench", "scaling")."""
    return os.path.join(project_dir(), *parts)


def output_folder(path, tool):
    """Makes the output folder path (-o) of a tool if it does not exist;
    FlapFoamError naming the tool and the reason if it cannot."""
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as e:
        raise FlapFoamError("%s: -o %s: cannot make the folder: %s"
                            % (tool, path, e))
    return path
