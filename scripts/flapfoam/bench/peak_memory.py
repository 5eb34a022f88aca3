# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Run a command and report the peak memory of the solver processes it starts.

    flapfoam peak_memory [-p NAME] [-o FILE] -- COMMAND [ARGS ...]

Polls /proc every 0.2 s for processes whose name is NAME (default
overPimpleDyMFoam) that descend from COMMAND (so that other runs on the
machine are not counted) and records each one's VmHWM (its peak resident set size,
kept by the kernel, so short peaks between polls are not missed).  At the end
prints, and writes to FILE, the sum of the peaks over the processes (the
ranks of a parallel run) in MiB.  Exits with the command's exit status.
"""

import argparse
import os
import subprocess
import sys
import time
from flapfoam.errors import run_tool


def hwm_kib(pid):
    """VmHWM of a process in KiB, or None if it is gone."""
    try:
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1])
    except (OSError, ValueError):
        return None
    return None


def parent(pid):
    """Parent pid of a process, or None if it is gone."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            # pid (comm) state ppid ...: comm may hold spaces
            return int(f.read().rsplit(")", 1)[1].split()[1])
    except (OSError, ValueError, IndexError):
        return None


def descends(pid, ancestor):
    while pid and pid > 1:
        if pid == ancestor:
            return True
        pid = parent(pid)
    return False


def solver_pids(name, ancestor):
    pids = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/comm" % entry) as f:
                if f.read().strip() != name[:15]:
                    continue
        except OSError:
            continue
        if descends(int(entry), ancestor):
            pids.append(int(entry))
    return pids


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-p", dest="process", default="overPimpleDyMFoam")
    parser.add_argument("-o", dest="output")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        sys.exit("peak_memory: no command")

    proc = subprocess.Popen(command)
    peaks = {}
    while proc.poll() is None:
        for pid in solver_pids(args.process, proc.pid):
            kib = hwm_kib(pid)
            if kib is not None:
                peaks[pid] = max(peaks.get(pid, 0), kib)
        time.sleep(0.2)

    total_mib = sum(peaks.values())/1024.0
    line = "%.1f MiB peak resident memory of %d %s process(es)" \
        % (total_mib, len(peaks), args.process)
    print("peak_memory: " + line)
    if args.output:
        with open(args.output, "w") as f:
            f.write("%.3f %d\n" % (total_mib, len(peaks)))
    return proc.returncode


if __name__ == "__main__":
    sys.exit(run_tool(main))
