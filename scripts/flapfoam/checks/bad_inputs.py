# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The bad-input scenarios of a test folder, read from a table and run: for
each row a fresh copy of a base run folder (or none), the row's edits, its
command, then the verdict: an error exit (not 0, not a hang, not a signal)
whose output holds every expected text, and nothing made where the row
says so.  One "PASS bad input NAME ..." or "FAIL bad input NAME ..." line a
row; exit status 1 if one fails.

    flapfoam bad_inputs TABLE [-base DIR] [-dir DIR] [-var NAME=VALUE]...
        [-only NAME]

The table (a text file; # starts a comment) is rows, each a "badInput
NAME" line and the lines below it:

    edit set FILE ENTRY VALUE     foamDictionary FILE -entry ENTRY -set VALUE
    edit add FILE ENTRY VALUE     the same with -add
    edit remove FILE ENTRY        the same with -remove
    edit sed FILE EXPRESSION      sed -i -e EXPRESSION FILE
    edit write FILE TEXT          FILE is TEXT (\\n a new line)
    edit append FILE TEXT         TEXT added at FILE's end
    edit delete FILE              FILE removed
    run COMMAND ARGS...           the command (words as a shell splits them)
    exit N                        exactly this exit status (default: any
                                  error exit)
    expect TEXT                   the output holds TEXT
    expectRegex EXPRESSION        a line of the output matches EXPRESSION
                                  (Python re, ^ and $ at each line)
    unchanged FOLDER              FOLDER's listing is the same after the run
    timeout SECONDS               a run past it is a hang (default 60)

Every row needs run and an expect or expectRegex.  With -base, each row
runs in DIR/NAME (a copy of the base, removed when the row passes); without
it, in the folder the runner was started in, its output in DIR/log.NAME.
${NAME} anywhere in a row is the value of -var NAME=VALUE; ${dir} is DIR,
${case} in run and expect lines the folder the row runs in.
"""

import argparse
import dataclasses
import os
import re
import shlex
import shutil
import subprocess
import sys
from dataclasses import dataclass, field

from flapfoam.errors import FlapFoamError, run_tool

EDITS = {"set": 3, "add": 3, "remove": 2, "sed": 2, "write": 2,
         "append": 2, "delete": 1}
KEYS = ("edit", "run", "exit", "expect", "expectRegex", "unchanged",
        "timeout")


@dataclass
class BadInput:
    """A row of the table: what to change, what to run, what to expect."""
    name: str
    line: int
    edits: list = field(default_factory=list)
    run: list = field(default_factory=list)
    exit: int = None
    expect: list = field(default_factory=list)   # (regex?, text), in order
    unchanged: list = field(default_factory=list)
    timeout: float = 60.0


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


def _add(row, key, rest, where):
    if key == "edit":
        row.edits.append(_edit(rest, where))
    elif key == "run":
        row.run = shlex.split(rest)
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
    else:
        row.timeout = _number(float, rest, where)


def read_table(path, variables):
    """The rows of the table at path, ${NAME} replaced from variables."""
    rows = []
    with open(path) as fh:
        lines = fh.read().splitlines()
    for number, raw in enumerate(lines, 1):
        where = "%s line %d" % (path, number)
        text = substitute(raw.strip(), variables, where)
        if not text or text.startswith("#"):
            continue
        key, _, rest = text.partition(" ")
        rest = rest.strip()
        if key == "badInput":
            if not rest or any(r.name == rest for r in rows):
                raise FlapFoamError("%s: badInput '%s': a name not used "
                                    "before is allowed" % (where, rest))
            rows.append(BadInput(rest, number))
        elif key not in KEYS:
            raise FlapFoamError("%s: '%s': one of badInput %s is allowed"
                                % (where, key, " ".join(KEYS)))
        elif not rows:
            raise FlapFoamError("%s: '%s' before the first badInput line"
                                % (where, key))
        else:
            _add(rows[-1], key, rest, where)
    for r in rows:
        if not r.run or not r.expect:
            raise FlapFoamError("%s line %d: badInput %s needs a run line and "
                                "an expect or expectRegex line"
                                % (path, r.line, r.name))
    if not rows:
        raise FlapFoamError("%s: no badInput row" % path)
    return rows


def apply_edit(words, folder):
    """One edit in folder; an error names the edit if it fails."""
    verb, path = words[0], os.path.join(folder, words[1])
    # From the folder, as a dictionary's #include may be relative to it
    if verb in ("set", "add", "remove"):
        command = ["foamDictionary", words[1], "-entry", words[2], "-" + verb]
        command += words[3:]
    elif verb == "sed":
        command = ["sed", "-i", "-e", words[2], words[1]]
    else:
        command = None
        if verb == "delete":
            os.remove(path)
        else:
            with open(path, "w" if verb == "write" else "a") as fh:
                fh.write(words[2].replace("\\n", "\n") + "\n")
    if command:
        done = subprocess.run(command, cwd=folder, text=True,
                              stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE)
        if done.returncode != 0:
            raise FlapFoamError("edit %s failed: %s"
                                % (" ".join(words), done.stderr.strip()[-300:]))


def listing(folder):
    return sorted(os.listdir(folder)) if os.path.isdir(folder) else None


@dataclass
class Outcome:
    """What a row's run gave: its exit status (None: a hang), output."""
    rc: int
    output: str
    changed: list


def run_row(row, folder, log):
    """Run the row's command in folder, its output in log."""
    before = [listing(os.path.join(folder, u)) for u in row.unchanged]
    try:
        done = subprocess.run(row.run, cwd=folder, stdin=subprocess.DEVNULL,
                              stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True,
                              errors="replace", timeout=row.timeout)
        rc, output = done.returncode, done.stdout
    except subprocess.TimeoutExpired as e:
        rc, output = None, (e.output or b"").decode(errors="replace")
    except OSError as e:
        rc, output = 127, "%s: %s" % (row.run[0], e.strerror)
    changed = [u for u, b in zip(row.unchanged, before)
               if listing(os.path.join(folder, u)) != b]
    with open(log, "w") as fh:
        fh.write(output)
    return Outcome(rc, output, changed)


def found(expectation, text):
    """Whether text holds an expectation (regex?, pattern)."""
    regex, pattern = expectation
    return bool(re.search(pattern, text, re.M)) if regex else pattern in text


def said(row, output):
    """The output's line that holds the row's first expected text."""
    for line in output.splitlines():
        if found(row.expect[0], line):
            return line.strip()[:200]
    return ""


def verdict(row, outcome):
    """(passed, text) of a row's outcome."""
    rc = outcome.rc
    if rc is None:
        problems = ["no exit within %g s (a hang)" % row.timeout]
    elif row.exit is not None:
        problems = [] if rc == row.exit else ["exit %d, not %d" % (rc, row.exit)]
    elif rc == 0 or rc < 0 or rc == 124 or rc >= 128:
        problems = ["exit %d: not an error exit (a signal, a timeout or "
                    "success)" % rc]
    else:
        problems = []
    problems += ["output lacks [%s]" % e[1] for e in row.expect
                 if not found(e, outcome.output)]
    problems += ["%s/ changed" % u for u in outcome.changed]
    if problems:
        return False, "bad input %s: %s" % (row.name, "; ".join(problems))
    return True, "bad input %s (exit %d): %s" % (row.name, rc,
                                                 said(row, outcome.output))


def check_row(row, settings):
    """Set up, run and judge one row; True if it passed."""
    slug = re.sub(r"[^A-Za-z0-9_.+-]+", "_", row.name)
    if settings.base:
        folder = os.path.join(settings.dir, slug)
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(settings.base, folder, symlinks=True)
        log = os.path.join(folder, "log")
    else:
        folder, log = os.getcwd(), os.path.join(settings.dir, "log." + slug)
    row = dataclasses.replace(
        row, run=[w.replace("${case}", folder) for w in row.run],
        expect=[(r, t.replace("${case}", folder)) for r, t in row.expect])
    try:
        for words in row.edits:
            apply_edit(words, folder)
    except (FlapFoamError, OSError) as e:
        print("FAIL bad input %s: %s" % (row.name, e))
        return False
    outcome = run_row(row, folder, log)
    passed, text = verdict(row, outcome)
    print("%s %s" % ("PASS" if passed else "FAIL", text))
    if passed and settings.base:
        shutil.rmtree(folder)
    elif not passed:
        print("    (the output: %s)\n%s" % (log, outcome.output[-1500:]))
    return passed


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="flapfoam bad_inputs", description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("table")
    parser.add_argument("-base", help="run folder copied for each row")
    parser.add_argument("-dir", default=os.path.join(
        os.environ.get("TMPDIR", "/tmp"), "flapFoam-badInputs"),
        help="where the copies and logs go")
    parser.add_argument("-var", action="append", default=[],
                        metavar="NAME=VALUE", help="${NAME} in the table")
    parser.add_argument("-only", help="run only this row")
    settings = parser.parse_args(argv)
    variables = {"dir": settings.dir, "case": "${case}"}   # case: per row
    for v in settings.var:
        name, sep, value = v.partition("=")
        if not sep or not re.fullmatch(r"\w+", name):
            raise FlapFoamError("-var '%s': NAME=VALUE is allowed" % v)
        variables[name] = value
    if settings.base and not os.path.isdir(settings.base):
        raise FlapFoamError("-base '%s': no such folder" % settings.base)
    rows = read_table(settings.table, variables)
    if settings.only:
        rows = [r for r in rows if r.name == settings.only]
        if not rows:
            raise FlapFoamError("-only '%s': no such row in %s"
                                % (settings.only, settings.table))
    os.makedirs(settings.dir, exist_ok=True)
    results = [check_row(r, settings) for r in rows]
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(run_tool(main))
