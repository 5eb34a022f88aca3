# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The table that flapfoam scenarios runs, read: its rows, ${NAME} replaced,
every keyword checked against its row's kind (a text file; # starts a
comment).  A row is a "badInput NAME" or a "scenario NAME" line and the
lines below it:

    edit set FILE ENTRY VALUE     foamDictionary FILE -entry ENTRY -set VALUE
    edit add FILE ENTRY VALUE     the same with -add
    edit remove FILE ENTRY        the same with -remove
    edit sed FILE EXPRESSION      sed -i -e EXPRESSION FILE
    edit write FILE TEXT          FILE is TEXT (\\n a new line)
    edit append FILE TEXT         TEXT added at FILE's end
    edit delete FILE              FILE removed
    run COMMAND ARGS...           a command (words as a shell splits them):
                                  a badInput has one, a scenario one or
                                  more, run in order (a restart: the same
                                  run folder again)
    expect TEXT                   the output holds TEXT
    expectRegex EXPRESSION        a line of the output matches EXPRESSION
                                  (Python re, ^ and $ at each line)
    unchanged FOLDER              FOLDER's listing is the same after the
                                  run(s)
    timeout SECONDS               a run past it is a hang (default 60 for a
                                  badInput, 1800 for a scenario)
  badInput only:
    exit N                        exactly this exit status (default: any
                                  error exit)
  scenario only, after its runs, in the table's order:
    check COMMAND ARGS...         a command's PASS/FAIL lines (or, without
                                  any, its exit status) are the verdict
    same A B FILE...              A/FILE and B/FILE byte for byte, each FILE
    reference RUN REFERENCE       RUN's joints.dat against the one kept in
                                  the folder REFERENCE, within the tolerance
                                  written in REFERENCE/reference

A badInput needs an expect or expectRegex line.
"""

import re
import shlex
from dataclasses import dataclass, field

from flapfoam.errors import FlapFoamError

EDITS = {"set": 3, "add": 3, "remove": 2, "sed": 2, "write": 2,
         "append": 2, "delete": 1}
COMMON = ("edit", "run", "expect", "expectRegex", "unchanged", "timeout")
KEYS = {"badInput": COMMON + ("exit",),
        "scenario": COMMON + ("check", "same", "reference")}
TIMEOUT = {"badInput": 60.0, "scenario": 1800.0}
CHECK_WORDS = {"check": 1, "same": 3, "reference": 2}   # at least


@dataclass
class Row:
    """A row of the table: what to change, what to run, what to expect."""
    kind: str
    name: str
    line: int
    edits: list = field(default_factory=list)
    runs: list = field(default_factory=list)     # word lists, in order
    exit: int = None
    expect: list = field(default_factory=list)   # (regex?, text), in order
    unchanged: list = field(default_factory=list)
    timeout: float = None
    checks: list = field(default_factory=list)   # (key, words), in order


def substitute(text, variables, where):
    """${NAME} replaced by variables[NAME]; an unknown NAME is an error
    naming where it was found."""
    def value(match):
        name = match.group(1)
        if name not in variables:
            raise FlapFoamError(
                "%s: ${%s}: no such variable (given: %s)"
                % (where, name, " ".join(sorted(variables)) or "none"))
        return variables[name]
    return re.sub(r"\$\{(\w+)\}", value, text)


def _number(kind, text, where):
    try:
        value = kind(text)
    except ValueError:
        value = None
    if value is None or value < 0:
        raise FlapFoamError("%s: '%s': a number >= 0 is allowed"
                            % (where, text))
    return value


def _edit(rest, where):
    """An edit line's words: [verb, args..., last word = rest of the line]."""
    verb = rest.split(None, 1)[0] if rest else ""
    if verb not in EDITS:
        raise FlapFoamError("%s: edit '%s': one of %s is allowed"
                            % (where, verb, " ".join(EDITS)))
    words = rest.split(None, EDITS[verb])
    if len(words) != EDITS[verb] + 1:
        raise FlapFoamError("%s: edit %s needs %d words after it, got '%s'"
                            % (where, verb, EDITS[verb], rest))
    return words


def _words(key, rest, where):
    words = shlex.split(rest)
    if len(words) < CHECK_WORDS.get(key, 1):
        raise FlapFoamError("%s: %s needs at least %d words, got '%s'"
                            % (where, key, CHECK_WORDS.get(key, 1), rest))
    return words


def _add(row, key, rest, where):
    if key == "edit":
        row.edits.append(_edit(rest, where))
    elif key == "run":
        row.runs.append(_words(key, rest, where))
    elif key == "exit":
        row.exit = _number(int, rest, where)
    elif key == "expect":
        row.expect.append((False, rest))
    elif key == "expectRegex":
        try:
            re.compile(rest)
        except re.error as e:
            raise FlapFoamError("%s: expectRegex '%s': %s" % (where, rest, e))
        row.expect.append((True, rest))
    elif key == "unchanged":
        row.unchanged.append(rest)
    elif key == "timeout":
        row.timeout = _number(float, rest, where)
    else:
        row.checks.append((key, _words(key, rest, where)))


def _line(rows, text, number, where):
    """One line of the table added to rows."""
    key, _, rest = text.partition(" ")
    rest = rest.strip()
    if key in KEYS:
        if not rest or any(r.name == rest for r in rows):
            raise FlapFoamError("%s: %s '%s': a name not used before is "
                                "allowed" % (where, key, rest))
        rows.append(Row(key, rest, number))
    elif not rows:
        raise FlapFoamError("%s: '%s' before the first %s line"
                            % (where, key, " or ".join(KEYS)))
    elif key not in KEYS[rows[-1].kind]:
        raise FlapFoamError("%s: '%s' in %s %s: one of %s is allowed"
                            % (where, key, rows[-1].kind, rows[-1].name,
                               " ".join(list(KEYS) + list(KEYS[rows[-1].kind]))))
    else:
        _add(rows[-1], key, rest, where)


def _complete(row, path):
    """The row's defaults; an error if it lacks what its kind needs."""
    where = "%s line %d: %s %s" % (path, row.line, row.kind, row.name)
    if row.kind == "badInput" and (len(row.runs) != 1 or not row.expect):
        raise FlapFoamError("%s needs one run line and an expect or "
                            "expectRegex line" % where)
    if not row.runs:
        raise FlapFoamError("%s needs a run line" % where)
    if row.timeout is None:
        row.timeout = TIMEOUT[row.kind]


def read_table(path, variables):
    """The rows of the table at path, ${NAME} replaced from variables."""
    rows = []
    with open(path) as fh:
        lines = fh.read().splitlines()
    for number, raw in enumerate(lines, 1):
        where = "%s line %d" % (path, number)
        text = substitute(raw.strip(), variables, where)
        if text and not text.startswith("#"):
            _line(rows, text, number, where)
    for r in rows:
        _complete(r, path)
    if not rows:
        raise FlapFoamError("%s: no badInput or scenario row" % path)
    return rows
