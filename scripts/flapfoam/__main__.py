# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The flapfoam command: one entry to the package's tools.

    flapfoam TOOL [options]      run the tool (its own -h for its options)
    flapfoam -help               the tools and what each does

bin/flapfoam runs this with the interpreter of FLAPFOAM_PYTHON (etc/bashrc:
Debian's /usr/bin/python3, which has numpy, scipy, h5py and matplotlib), so
that another python3 first on the PATH (a module's, conda's, pyenv's) does
not matter; a pip install of the package gets the same command
([project.scripts]).  A tool is a module of the package that runs as a
program (it has a main guard); the list reads the modules' sources, so it
needs none of their dependencies.
"""

import ast
import os
import runpy
import sys


def tools():
    """{name: first line of its docstring} of the package's runnable
    modules."""
    here = os.path.dirname(os.path.abspath(__file__))
    found = {}
    for name in sorted(os.listdir(here)):
        if not name.endswith(".py") or name.startswith("_"):
            continue
        with open(os.path.join(here, name)) as fh:
            source = fh.read()
        if 'if __name__ == "__main__":' not in source:
            continue
        doc = ast.get_docstring(ast.parse(source)) or ""
        first = " ".join(doc.split("\n\n")[0].split()).split(". ")[0]
        found[name[:-3]] = first if len(first) <= 96 else \
            first[:93].rsplit(" ", 1)[0] + " ..."
    return found


def usage(out):
    out.write("usage: flapfoam TOOL [options] (flapfoam TOOL -h: the "
              "tool's options)\n\ntools:\n")
    for name, doc in tools().items():
        out.write("  %-24s %s\n" % (name, doc))


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] in ("-h", "-help", "--help"):
        usage(sys.stdout)
        return 0
    name = argv[0]
    if name not in tools():
        sys.stderr.write("flapfoam: no tool '%s' (flapfoam -help lists them)"
                         "\n" % name)
        return 2
    sys.argv = ["flapfoam " + name] + argv[1:]
    runpy.run_module("flapfoam." + name, run_name="__main__", alter_sys=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
