# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
A drone case flown by the quasi-steady (QS) model in copies of a run
folder: the studies' one way to set a case up (its Allrun -model
quasiSteady, one cycle, no plots), to run rigidBodySimulate -bodyLoad
aerodynamics in a folder, and to read the joint map of its log (qs_sweep,
gain_sweep, trim, floquet).
"""

import json
import math
import os
import re
import shutil
import subprocess
import time
from dataclasses import dataclass

from flapfoam.errors import FlapFoamError


class StudyError(FlapFoamError):
    """Bad input or a failed run of a study: the message names the option
    or file, the value and what is allowed."""


def foam_dictionary(*args):
    """The output of foamDictionary -precision 17 ARGS (StudyError if it
    fails): an entry set writes the whole file again, every number at 17
    digits (foamDictionary's default 6 would round the others: pi to
    3.14159)."""
    run = subprocess.run(["foamDictionary", "-precision", "17"] + list(args),
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True)
    if run.returncode != 0:
        raise StudyError("foamDictionary %s: %s" % (" ".join(args),
                                                    run.stdout[-300:]))
    return run.stdout.strip()


def set_up(case, folder, options):
    """The case's QS run folder of one cycle, made afresh (an earlier
    FOLDER removed) by its Allrun -model quasiSteady -cycles 1 -case FOLDER
    -noPlot OPTIONS (e.g. -variant V -deltaT DT), its output in
    FOLDER.log; StudyError if it fails."""
    allrun = os.path.join(case, "Allrun")
    if not os.path.isfile(allrun):
        raise StudyError("-case %s: no Allrun there (allowed: a drone case"
                         " folder, e.g. cases/bodyWingDrone)" % case)
    log = folder + ".log"
    shutil.rmtree(folder, ignore_errors=True)
    command = [allrun, "-model", "quasiSteady", "-cycles", "1", "-case",
               folder, "-noPlot"] + list(options)
    with open(log, "w") as out:
        rc = subprocess.call(command, stdout=out, stderr=subprocess.STDOUT,
                             stdin=subprocess.DEVNULL)
    if rc != 0:
        with open(log) as f:
            tail = f.read()[-400:]
        raise StudyError("%s failed (exit %d, %s): %s"
                         % (" ".join(command), rc, log, tail))
    return folder


def simulate(case, log, options=()):
    """(exit status, seconds) of rigidBodySimulate -case CASE -bodyLoad
    aerodynamics OPTIONS, its output in CASE/LOG."""
    start = time.time()
    with open(os.path.join(case, log), "w") as out:
        rc = subprocess.call(["rigidBodySimulate", "-case", case,
                              "-bodyLoad", "aerodynamics"] + list(options),
                             stdout=out, stderr=subprocess.STDOUT,
                             stdin=subprocess.DEVNULL)
    return rc, time.time() - start


@dataclass
class Joint:
    """One q index of rigidBodySimulate's joint state map: its body, its
    joint type (Pz, Ry, ...) and the imposedMotion entry that prescribes
    it (None: free)."""
    index: int
    body: str
    type: str
    motion: str = None

    @property
    def translation(self):
        return self.type in ("Px", "Py", "Pz")


def linked(group):
    """[(NAME, sign)] of a linked name NAME+-NAME2+...: one value for
    several dictionary entries, negated after a - (the mirrored wings'
    entries, e.g. flapping.amplitude+-rightFlapping.amplitude)."""
    return [(n[1:], -1) if n.startswith("-") else (n, 1)
            for n in group.split("+")]


def set_placeholders(dictionary, groups, entry_of, prefix):
    """Sets every entry of the groups' linked names (entry_of(NAME): its
    path in dictionary) to the placeholder PREFIX_<i> of group i, or
    PREFIXNeg_<i> where the name is negated (fill_placeholders)."""
    for i, group in enumerate(groups):
        for name, sign in linked(group):
            foam_dictionary("-entry", entry_of(name), "-set", "%s%s_%d" % (
                prefix, "Neg" if sign < 0 else "", i), dictionary)


def fill_placeholders(text, prefix, values):
    """text with PREFIX_<i> set to values[i] and PREFIXNeg_<i> to
    -values[i] (set_placeholders)."""
    for i, v in enumerate(values):
        text = text.replace("%s_%d;" % (prefix, i), "%r;" % float(v))
        text = text.replace("%sNeg_%d;" % (prefix, i), "%r;" % -float(v))
    return text


def joint_map(log_text):
    """[Joint] of a rigidBodySimulate log, in q index order."""
    joints = []
    for m in re.finditer(r"q\[(\d+)\]: body (\S+), joint (\w+)"
                         r"(?:, prescribed by (\S+))?", log_text):
        joints.append(Joint(int(m.group(1)), m.group(2), m.group(3),
                            m.group(4)))
    return joints


def write_summary(path, keys):
    """keys merged into the JSON object of path (made if absent): each
    study writes its own keys of a results folder's summary.json."""
    summary = {}
    if os.path.isfile(path):
        with open(path) as f:
            summary = json.load(f)
    summary.update(keys)
    with open(path, "w") as f:
        json.dump(summary, f, indent=1)
        f.write("\n")


def check_ranges(parser, args, positive=(), counts=()):
    """parser.error for an option of args (argparse dest names) out of its
    range: positive, a finite number > 0 (None: not given); counts, an
    integer >= 1."""
    option = {a.dest: a.option_strings[0] for a in parser._actions
              if a.option_strings}
    for name in positive:
        v = getattr(args, name)
        if v is not None and not (v > 0 and math.isfinite(v)):
            parser.error("%s %g: not allowed (> 0)" % (option[name], v))
    for name in counts:
        if getattr(args, name) < 1:
            parser.error("%s %d: not allowed (an integer >= 1)"
                         % (option[name], getattr(args, name)))
