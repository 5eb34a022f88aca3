# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Minimal OpenFOAM dictionary reader (enough for dynamicMeshDict; a file
with $macros or #include is expanded by foamDictionary first), the
rigidBodyMotionState of a time folder, and an entry set or removed by
OpenFOAM's foamDictionary.  numpy only.
"""

import re
import subprocess

import numpy as np


def _strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def expanded_text(path):
    """The file as OpenFOAM reads it: with $macros or #directives (#include,
    #calc, ...) the output of OpenFOAM's foamDictionary -expand (17 digits),
    else the file itself.  ValueError if foamDictionary cannot expand it."""
    with open(path) as f:
        text = f.read()
    if not re.search(r"(^|[\s{(;])[$#][\w{]", _strip_comments(text)):
        return text
    try:
        out = subprocess.run(["foamDictionary", "-expand", "-precision", "17",
                              path], capture_output=True, text=True)
    except FileNotFoundError:
        out = None
    if out is None or out.returncode != 0:
        why = "no foamDictionary on the PATH" if out is None else \
            " ".join((out.stderr or out.stdout).split()[-30:])
        raise ValueError("%s has $macros or #directives; reading it needs"
                         " OpenFOAM's foamDictionary -expand (source"
                         " etc/bashrc): %s" % (path, why))
    return out.stdout


def read_foam_dict(path):
    """Nested dict of an OpenFOAM dictionary file, read as OpenFOAM reads it
    ($macros, #include: expanded_text): sub-dictionaries as dicts, entries
    as lists of tokens (strings)."""
    text = _strip_comments(expanded_text(path))
    tokens = re.findall(r'"[^"]*"|[{}();]|[^\s{}();"]+', text)
    pos = 0

    def parse():
        nonlocal pos
        d = {}
        while pos < len(tokens):
            t = tokens[pos]
            if t == "}":
                pos += 1
                return d
            key = t
            pos += 1
            if pos < len(tokens) and tokens[pos] == "{":
                pos += 1
                d[key] = parse()
                continue
            value = []
            depth = 0
            while pos < len(tokens):
                t = tokens[pos]
                pos += 1
                if t == "(":
                    depth += 1
                elif t == ")":
                    depth -= 1
                elif t == ";" and depth == 0:
                    break
                value.append(t)
            d[key] = value
        return d

    return parse()


def read_state(path):
    """{q, qDot, qDdot: arrays, t: float} of a rigidBodyMotionState; an
    entry the file lacks (a hand-written state: no qDdot, no t) is not in
    the result."""
    with open(path) as f:
        text = f.read()
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    state = {}
    for key in ("q", "qDot", "qDdot"):
        m = re.search(r"\b%s\s+\d+\s*\(([^)]*)\)\s*;" % key, text)
        if m is None:
            m = re.search(r"\b%s\s+\(([^)]*)\)\s*;" % key, text)
        if m is not None:
            state[key] = np.array(m.group(1).split(), dtype=float)
    m = re.search(r"\bt\s+([^;\s]+)\s*;", text)
    if m is not None:
        state["t"] = float(m.group(1))
    return state


def multibody_coeffs(path):
    """The multibody motion's coefficients of a dynamicMeshDict: its
    eABAMeshMotionCoeffs, else the whole dictionary."""
    d = read_foam_dict(path)
    return d.get("eABAMeshMotionCoeffs", d)


def set_entry(path, entry, value):
    """foamDictionary -set ENTRY VALUE (value None: -remove) on the file.
    foamDictionary writes the whole file again: at 17 digits, not at its
    default 6, so that the other numbers stay as they were."""
    action = ["-remove"] if value is None else ["-set", value]
    subprocess.run(["foamDictionary", "-precision", "17", "-entry", entry]
                   + action + [path], check=True, stdout=subprocess.DEVNULL)

