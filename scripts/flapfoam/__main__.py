# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The flapfoam command: one entry to the package's tools.

    flapfoam TOOL [options]      run the tool (its own -h for its options)
    flapfoam -help               the tools, by subpackage, and what each does

bin/flapfoam runs this with the interpreter of FLAPFOAM_PYTHON (etc/bashrc:
Debian's /usr/bin/python3, which has numpy, scipy, h5py and matplotlib), so
that another python3 first on the PATH (a module's, conda's, pyenv's) does
not matter; a pip install of the package gets the same command
([project.scripts]).  A tool is a module of the package that runs as a
program (it has a main guard), in one of the package's subpackages; the
list reads the modules' sources, so it needs none of their dependencies.
"""

import ast
import importlib.util
import os
import sys


def tool_prefix(folder):
    """The TOOL_PREFIX a subpackage's __init__.py sets ("" if none): its
    tools are named prefix + module (scaling/model.py: scaling_model)."""
    with open(os.path.join(folder, "__init__.py")) as fh:
        for node in ast.parse(fh.read()).body:
            if isinstance(node, ast.Assign) and \
                    [t.id for t in node.targets] == ["TOOL_PREFIX"]:
                return node.value.value
    return ""


def first_sentence(source):
    doc = ast.get_docstring(ast.parse(source)) or ""
    first = " ".join(doc.split("\n\n")[0].split()).split(". ")[0]
    return first if len(first) <= 96 else \
        first[:93].rsplit(" ", 1)[0] + " ..."


def tools():
    """{name: (module, first line of its docstring)} of the package's
    runnable modules, in its subpackages; a name found twice is an error
    of the package (the unit tests check there is none)."""
    here = os.path.dirname(os.path.abspath(__file__))
    found = {}
    for sub in sorted(os.listdir(here)):
        folder = os.path.join(here, sub)
        if not os.path.isfile(os.path.join(folder, "__init__.py")):
            continue
        prefix = tool_prefix(folder)
        for name in sorted(os.listdir(folder)):
            if not name.endswith(".py") or name.startswith("_"):
                continue
            with open(os.path.join(folder, name)) as fh:
                source = fh.read()
            if 'if __name__ == "__main__":' not in source:
                continue
            tool = prefix + name[:-3]
            if tool in found:
                raise RuntimeError("flapfoam: two tools named " + tool)
            found[tool] = ("flapfoam.%s.%s" % (sub, name[:-3]),
                           first_sentence(source))
    return dict(sorted(found.items()))


def subpackage_title(sub):
    """What a subpackage holds: its docstring up to the first colon."""
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, sub, "__init__.py")) as fh:
        return first_sentence(fh.read()).split(":")[0]


def usage(out):
    """The tools under a heading per subpackage ("checks: Checks, ...")."""
    out.write("usage: flapfoam TOOL [options] (flapfoam TOOL -h: the "
              "tool's options)\n")
    groups = {}
    for name, (module, doc) in tools().items():
        groups.setdefault(module.split(".")[1], []).append((name, doc))
    for sub, listed in sorted(groups.items()):
        out.write("\n%s: %s\n" % (sub, subpackage_title(sub)))
        for name, doc in listed:
            out.write("  %-24s %s\n" % (name, doc))


def run(module, argv):
    """Run the tool's module as python -m runs it (its own __main__ in
    sys.modules while it runs), with sys.argv = argv: argv[0] "flapfoam
    TOOL" is the prog its argparse usage names (runpy would put the module's
    file name there)."""
    spec = importlib.util.find_spec(module)
    code = spec.loader.get_code(module)
    tool = importlib.util.module_from_spec(spec)
    tool.__name__ = "__main__"
    saved = sys.modules["__main__"], sys.argv
    sys.modules["__main__"], sys.argv = tool, list(argv)
    try:
        exec(code, tool.__dict__)
    finally:
        sys.modules["__main__"], sys.argv = saved


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] in ("-h", "-help", "--help"):
        usage(sys.stdout)
        return 0
    name = argv[0]
    found = tools()
    if name not in found:
        sys.stderr.write("flapfoam: no tool '%s' (flapfoam -help lists them)"
                         "\n" % name)
        return 2
    # -help, OpenFOAM's spelling, is every tool's -h (argparse would read
    # it as -h with the value 'elp')
    run(found[name][0], ["flapfoam " + name]
        + ["-h" if a == "-help" else a for a in argv[1:]])
    return 0


if __name__ == "__main__":
    sys.exit(main())
