# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
A command run the way a program runs it (a parameter sweep, an optimiser, a
workflow manager): its output captured through pipes, read to their end.

    flapfoam captured_run [-timeout S] [-expect TEXT] [-name NAME] -- COMMAND...

Runs COMMAND in a session of its own with stdout and stderr captured
(subprocess.run(capture_output=True)), then prints one PASS or FAIL line a
condition:
  - NAME returns: the pipes reached their end within S seconds (default
    600: a guard against a hang, not a timing: a run that leaves a
    process holding its output never returns);
  - NAME exit 0;
  - NAME its last line starts with TEXT (with -expect);
  - NAME leaves nothing running: no process of its session is left once
    it has returned.
The exit status is non-zero if any failed.  numpy-free.
"""

import argparse
import os
import signal
import subprocess
import sys
import time

from flapfoam.harness.checklist import Checks
from flapfoam.errors import run_tool


def session_processes(sid):
    """PIDs of the processes of session sid (from /proc)."""
    out = []
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % name) as fh:
                fields = fh.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[2]) == sid and fields[0] != "Z":
            out.append(int(name))
    return out


def run(command, timeout):
    """(returned, exit status, stdout text, seconds, processes left)."""
    start = time.monotonic()
    proc = subprocess.Popen(command, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                            process_group=0)
    try:
        out, _ = proc.communicate(timeout=timeout)
        returned = True
    except subprocess.TimeoutExpired:
        returned, out = False, b""
    seconds = time.monotonic() - start
    left = session_processes(proc.pid)
    if not returned or left:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
    return returned, proc.returncode, out.decode(errors="replace"), \
        seconds, left


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-timeout", type=float, default=600,
                        help="seconds before it counts as a hang (600)")
    parser.add_argument("-expect", help="the start of its last line")
    parser.add_argument("-name", default="captured", help="name on the lines")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args(argv)
    command = args.command[1:] if args.command[:1] == ["--"] \
        else args.command
    if not command:
        parser.error("no COMMAND (after --)")
    if not args.timeout > 0:
        parser.error("-timeout %g: a number of seconds > 0 is allowed"
                     % args.timeout)
    returned, rc, out, seconds, left = run(command, args.timeout)
    check = Checks()
    name = args.name
    check(returned, "%s returns under captured pipes: %s" % (
        name, "its output's end read after %.1f s" % seconds if returned
        else "no end of its output within %g s (a process it started "
        "holds the pipe)" % args.timeout))
    if returned:
        last = (out.strip().splitlines() or [""])[-1]
        check(rc == 0, "%s exit %s" % (name, rc))
        if args.expect is not None:
            check(last.startswith(args.expect), "%s last line '%s'%s"
                  % (name, last[:160], "" if last.startswith(args.expect)
                     else " (expected '%s...')" % args.expect))
    check(not left, "%s leaves nothing running%s" % (
        name, "" if not left else ": %d process(es) of its session left "
        "(%s)" % (len(left), " ".join(map(str, left)))))
    return 0 if check.ok else 1


if __name__ == "__main__":
    sys.exit(run_tool(main))
