# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The scenarios of a test folder, read from a table and run: a bad input, a
case run, a restart, each a row.  For each row a fresh copy of a base run
folder (or none), the row's edits, its command(s), then the verdict:

- badInput: an error exit (not 0, not a hang, not a signal) whose output
  holds every expected text, and nothing made where the row says so; one
  "PASS bad input NAME ..." or "FAIL bad input NAME ..." line;
- scenario: every run exits 0 without a "FAIL " line of its own (one
  "PASS [NAME] ..." line a run), the expected texts in their output, then
  its checks, each with its own PASS/FAIL lines: a command's (labelled
  [NAME]), files byte for byte, joints.dat against a reference kept in
  results/ with its tolerance.

Exit status 1 if a row fails.

    flapfoam scenarios TABLE [-base DIR] [-dir DIR] [-var NAME=VALUE]...
        [-only NAME] [-updateReferences]

The table's format: flapfoam.harness.scenario_table (below).  With -base,
each row runs in DIR/NAME (a copy of the base, removed when a badInput
passes); without it, in the folder the runner was started in, the output in
DIR/log.NAME (a scenario of several runs: DIR/log.NAME.1, .2, ...).
${NAME} anywhere in a row is the value of -var NAME=VALUE; ${dir} is DIR,
${case} in run and expect lines the folder the row runs in.
-updateReferences writes each reference from its run instead of comparing
(after a change that moves the results: say why in the commit).
"""

import argparse
import dataclasses
import filecmp
import os
import re
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass

from flapfoam.harness import scenario_table
from flapfoam.checks.check_run import JointsComparison, check_compare
from flapfoam.harness.scenario_table import read_table
from flapfoam.errors import FlapFoamError, run_tool

__doc__ += "\n" + scenario_table.__doc__.split("\n", 2)[2]


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
    """What a run gave: its exit status (None: a hang), output, seconds."""
    rc: int
    output: str
    seconds: float = 0.0


def run_command(words, folder, log, timeout):
    """words run in folder (no input), the output in log.  The output goes
    to the file, not a pipe: the command's exit ends the wait even when a
    child it left behind holds its output open (Allrun's progress tail)."""
    t0 = time.monotonic()
    with open(log, "w") as fh:
        try:
            rc = subprocess.run(words, cwd=folder, stdin=subprocess.DEVNULL,
                                stdout=fh, stderr=subprocess.STDOUT,
                                timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            rc = None
        except OSError as e:
            rc = 127
            fh.write("%s: %s\n" % (words[0], e.strerror))
    with open(log, errors="replace") as fh:
        output = fh.read()
    return Outcome(rc, output, time.monotonic() - t0)


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


def changed(row, folder, before):
    """The row's unchanged folders whose listing is not before's."""
    return ["%s/ changed" % u for u, b in zip(row.unchanged, before)
            if listing(os.path.join(folder, u)) != b]


def lacks(row, output):
    return ["output lacks [%s]" % e[1] for e in row.expect
            if not found(e, output)]


def exit_text(row, rc):
    """A run's exit status rc as the lines say it (None: a hang)."""
    return "no exit within %g s (a hang)" % row.timeout if rc is None \
        else "exit %d" % rc


def exit_problem(row, rc):
    """What is wrong with a bad input's exit status rc (None: a hang)."""
    if rc is None:
        return [exit_text(row, rc)]
    if row.exit is not None:
        return [] if rc == row.exit else ["exit %d, not %d" % (rc, row.exit)]
    if rc == 0 or rc < 0 or rc == 124 or rc >= 128:
        return ["exit %d: not an error exit (a signal, a timeout or "
                "success)" % rc]
    return []


def bad_input_verdict(row, outcome, folders):
    """(passed, text) of a bad input's outcome; folders: the unchanged
    folders that changed."""
    problems = exit_problem(row, outcome.rc) + lacks(row, outcome.output) \
        + folders
    if problems:
        return False, "bad input %s: %s" % (row.name, "; ".join(problems))
    return True, "bad input %s (exit %d): %s" % (row.name, outcome.rc,
                                                 said(row, outcome.output))


def run_bad_input(row, folder, log):
    """A bad input's run and verdict line; True if it passed."""
    before = [listing(os.path.join(folder, u)) for u in row.unchanged]
    outcome = run_command(row.runs[0], folder, log, row.timeout)
    passed, text = bad_input_verdict(row, outcome,
                                     changed(row, folder, before))
    print("%s %s" % ("PASS" if passed else "FAIL", text))
    if not passed:
        print("    (the output: %s)\n%s" % (log, outcome.output[-1500:]))
    return passed


def labelled(name, output):
    """The PASS/FAIL lines of output, [name] after the word; how many
    FAIL lines there were."""
    lines = [re.sub(r"^(PASS|FAIL) ", r"\1 [%s] " % name, line)
             for line in output.splitlines()
             if line.startswith(("PASS ", "FAIL "))]
    return lines, sum(line.startswith("FAIL") for line in lines)


def shown(words, width=120):
    """A command line as the PASS/FAIL lines show it: its start."""
    text = " ".join(words)
    return text if len(text) <= width else text[:width - 4] + " ..."


def run_scenario_runs(row, folder, logs):
    """The scenario's runs in order, a line each; the output of all, or
    None when one failed (the rest not run)."""
    outputs = []
    for k, (words, log) in enumerate(zip(row.runs, logs), 1):
        outcome = run_command(words, folder, log, row.timeout)
        lines, failed = labelled(row.name, outcome.output)
        what = shown(words)
        if len(row.runs) > 1:
            what = "run %d of %d: %s" % (k, len(row.runs), what)
        if outcome.rc != 0 or failed:
            print("\n".join(line for line in lines if line.startswith("FAIL")))
            print("FAIL [%s] %s: %s, %d FAIL lines of its own (see %s)"
                  % (row.name, what, exit_text(row, outcome.rc), failed, log))
            return None
        print("PASS [%s] %s completed (%.0f s, %d PASS lines of its own)"
              % (row.name, what, outcome.seconds, len(lines)))
        outputs.append(outcome.output)
    return "\n".join(outputs)


def check_same(row, words, folder):
    a, b, files = words[0], words[1], words[2:]
    differ = [f for f in files if not os.path.isfile(os.path.join(folder, a, f))
              or not os.path.isfile(os.path.join(folder, b, f))
              or not filecmp.cmp(os.path.join(folder, a, f),
                                 os.path.join(folder, b, f), shallow=False)]
    ok = not differ
    print("%s [%s] %s and %s byte for byte: %s" % (
        "PASS" if ok else "FAIL", row.name, a, b,
        " ".join(files) if ok else "differ or missing: " + " ".join(differ)))
    return ok


def reference_settings(path):
    """The JointsComparison of a reference folder's file "reference":
    lines "tolerance X" (needed), "columns a,b,..." and "rows all|last"."""
    entries = {}
    with open(path) as fh:
        for number, raw in enumerate(fh, 1):
            text = raw.split("#", 1)[0].split()
            if not text:
                continue
            if len(text) != 2 or text[0] not in ("tolerance", "columns",
                                                  "rows"):
                raise FlapFoamError(
                    "%s line %d: '%s': one of 'tolerance X', 'columns a,b', "
                    "'rows all|last' is allowed" % (path, number, raw.strip()))
            entries[text[0]] = text[1]
    if "tolerance" not in entries or \
            entries.get("rows", "all") not in ("all", "last"):
        raise FlapFoamError("%s: needs 'tolerance X' (rows all or last)"
                            % path)
    columns = entries.get("columns")
    return JointsComparison(columns.split(",") if columns else None,
                            float(entries["tolerance"]),
                            entries.get("rows", "all"))


def check_reference(row, words, folder, update):
    """RUN's joints.dat against (or, with update, written to) the
    reference folder's."""
    run, reference = (os.path.join(folder, w) for w in words)
    name = "[%s] %s against %s:" % (row.name, words[0], words[1])
    if update:
        # joints.dat of each start folder: what the comparison reads
        kept = os.path.join(reference, "postProcessing", "eABAMeshMotion")
        shutil.rmtree(kept, ignore_errors=True)
        shutil.copytree(os.path.join(run, "postProcessing", "eABAMeshMotion"),
                        kept, ignore=shutil.ignore_patterns("bodies.dat"))
        print("PASS %s reference written" % name)
        return True
    want = reference_settings(os.path.join(reference, "reference"))
    return check_compare(reference, run, name, want) == 0


def run_check(row, k, folder, settings):
    """The scenario's check k; True if it passed."""
    key, words = row.checks[k]
    if key == "same":
        return check_same(row, words, folder)
    if key == "reference":
        try:
            return check_reference(row, words, folder,
                                   settings.updateReferences)
        except (FlapFoamError, OSError) as e:
            print("FAIL [%s] reference %s: %s" % (row.name, " ".join(words), e))
            return False
    log = os.path.join(settings.dir, "log.%s.check%d" % (slug(row.name), k + 1))
    outcome = run_command(words, folder, log, row.timeout)
    lines, failed = labelled(row.name, outcome.output)
    if lines:
        print("\n".join(lines))
    if outcome.rc != 0 and not failed or not lines:
        print("%s [%s] %s%s" % (
            "PASS" if outcome.rc == 0 else "FAIL", row.name, " ".join(words),
            "" if outcome.rc == 0 else ": exit %s (see %s)" % (outcome.rc, log)))
    return outcome.rc == 0 and not failed


def run_scenario(row, folder, logs, settings):
    """A scenario's runs, expected texts and checks; True if all passed."""
    before = [listing(os.path.join(folder, u)) for u in row.unchanged]
    output = run_scenario_runs(row, folder, logs)
    if output is None:
        return False
    problems = lacks(row, output) + changed(row, folder, before)
    ok = not problems
    if row.expect or row.unchanged:
        print("%s [%s] %s" % ("PASS" if ok else "FAIL", row.name,
                              "; ".join(problems) if problems else
                              "the output: " + said(row, output)
                              if row.expect else "folders unchanged"))
    for k in range(len(row.checks)):
        ok = run_check(row, k, folder, settings) and ok
    return ok


def slug(name):
    return re.sub(r"[^A-Za-z0-9_.+-]+", "_", name)


def check_row(row, settings):
    """Set up, run and judge one row; True if it passed."""
    if settings.base:
        folder = os.path.join(settings.dir, slug(row.name))
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(settings.base, folder, symlinks=True)
        logs = [os.path.join(folder, "log")]
    else:
        folder, logs = os.getcwd(), [os.path.join(settings.dir,
                                                  "log." + slug(row.name))]
    if len(row.runs) > 1:
        logs = ["%s.%d" % (logs[0], k) for k in range(1, len(row.runs) + 1)]
    row = dataclasses.replace(
        row, runs=[[w.replace("${case}", folder) for w in r] for r in row.runs],
        expect=[(r, t.replace("${case}", folder)) for r, t in row.expect])
    try:
        for words in row.edits:
            apply_edit(words, folder)
    except (FlapFoamError, OSError) as e:
        print("FAIL %s %s: %s" % ("bad input" if row.kind == "badInput"
                                  else "[%s] edit" % row.name, row.name, e))
        return False
    if row.kind == "badInput":
        passed = run_bad_input(row, folder, logs[0])
        if passed and settings.base:
            shutil.rmtree(folder)
        return passed
    return run_scenario(row, folder, logs, settings)


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="flapfoam scenarios", description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("table")
    parser.add_argument("-base", help="run folder copied for each row")
    parser.add_argument("-dir", default=os.path.join(
        os.environ.get("TMPDIR", "/tmp"), "flapFoam-scenarios"),
        help="where the copies and logs go")
    parser.add_argument("-var", action="append", default=[],
                        metavar="NAME=VALUE", help="${NAME} in the table")
    parser.add_argument("-only", help="run only this row")
    parser.add_argument("-updateReferences", action="store_true",
                        help="write the references from the runs")
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
