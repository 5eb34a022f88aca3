# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Renders a CFD run's vortices and overset mesh with ParaView's pvbatch
(off-screen, on an Xvfb display of its own): a Q iso-surface and the cells
of every zone on a plane.

    flapfoam plot_flow RUN [-time T] [-q Q] [-o PREFIX] [-check]

RUN: a run folder of a drone case (overset, fields U and cellTypes).  The
time T (default: the latest written) is read reconstructed if RUN/T holds
U, else decomposed (RUN/processor0/T).  Only the calculated cells
(cellTypes 0) are drawn, so that the overlapping zones appear once.

    PREFIX-Q.png     the walls and the iso-surface Q = -q (default 1e5
                     1/s^2, about (U_ref/c)^2 of the drones: 4.8 m/s over
                     15 mm), coloured by the speed
    PREFIX-mesh.png  the cells on the plane z = the body's centre (the
                     stroke plane at rest), a colour a zone, holes and
                     fringes left out, the walls' outline
    PREFIX.json      the run, the time, the level, the iso-surface's
                     polygons, the largest Q, the slice's cells

Default PREFIX: RUN/plots/flow-<T>.  -check: a PASS/FAIL line each for
the iso-surface (polygons), the plane (cells) and the two PNGs (more than
16 colours: not blank), exit status 1 unless all pass.  Needs pvbatch and Xvfb (Debian's
paraview and xvfb: ./Allwmake installs them); pvbatch's output is kept in
PREFIX.log.  A missing run, time, field or program stops with a message.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys

from flapfoam.errors import FlapFoamError, run_tool

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                      "_pv_render.py")
TIMEOUT = 900


def times(folder):
    """{time value: name} of the time folders of folder that hold U."""
    found = {}
    for name in os.listdir(folder) if os.path.isdir(folder) else ():
        try:
            value = float(name)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(folder, name, "U")):
            found[value] = name
    return found


def pick_time(run, wanted):
    """(time name, ParaView case type) of the run's time wanted (None: the
    latest), reconstructed where it is, else decomposed."""
    kinds = (("Reconstructed Case", times(run)),
             ("Decomposed Case", times(os.path.join(run, "processor0"))))
    every = sorted(set(kinds[0][1]) | set(kinds[1][1]))
    if not every:
        raise FlapFoamError("%s: no time folder with a field U (nor in "
                            "processor0/): not a run, or nothing written "
                            "yet" % run)
    t = every[-1] if wanted is None else wanted
    for case_type, found in kinds:
        for value, name in found.items():
            if abs(value - t) <= 1e-9*max(1.0, abs(t)):
                return name, case_type
    raise FlapFoamError("-time %g: not a written time of %s (written: %s)"
                        % (t, run, " ".join("%g" % v for v in every)))


def foam_file(run):
    """The run's NAME.foam (made, empty, if it has none)."""
    for name in os.listdir(run):
        if name.endswith(".foam"):
            return os.path.join(run, name)
    path = os.path.join(run, os.path.basename(os.path.abspath(run))
                        + ".foam")
    open(path, "w").close()
    return path


def start_display():
    """(Xvfb process, DISPLAY) of a new server: Xvfb picks a free display
    number and writes it when it is ready (-displayfd); -noreset, as
    pvbatch's OpenGL probe is the first client to leave and a server
    resetting then refuses the render window ("bad X server
    connection")."""
    if shutil.which("Xvfb") is None or shutil.which("pvbatch") is None:
        raise FlapFoamError("plot_flow needs pvbatch and Xvfb (Debian: "
                            "apt-get install paraview xvfb; ./Allwmake "
                            "installs them)")
    read_end, write_end = os.pipe()
    server = subprocess.Popen(
        ["Xvfb", "-displayfd", str(write_end), "-screen", "0",
         "1600x1200x24", "-nolisten", "tcp", "-noreset"],
        pass_fds=(write_end,),
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_end)
    number = b""
    while not number.endswith(b"\n"):
        c = os.read(read_end, 1)
        if not c:
            break
        number += c
    os.close(read_end)
    if not number.strip().isdigit():
        server.kill()
        raise FlapFoamError("Xvfb did not start (no display number)")
    return server, ":" + number.decode().strip()


def render(run, time_name, case_type, level, prefix):
    """Runs the pvbatch script; its numbers (the 'render:' line)."""
    server, display = start_display()
    log = prefix + ".log"
    try:
        with open(log, "w") as fh:
            rc = subprocess.call(
                ["pvbatch", SCRIPT, foam_file(run), time_name, repr(level),
                 prefix, case_type], stdout=fh, stderr=subprocess.STDOUT,
                env=dict(os.environ, DISPLAY=display), timeout=TIMEOUT)
    finally:
        server.terminate()
        server.wait()
    with open(log, errors="replace") as fh:
        lines = [x for x in fh if x.startswith("render: ")]
    if rc != 0 or not lines:
        raise FlapFoamError("pvbatch failed (exit %d) on %s at t = %s: see "
                            "%s" % (rc, run, time_name, log))
    return json.loads(lines[-1][len("render: "):])


def colours(png):
    """The number of distinct colours of a PNG (matplotlib reads it)."""
    import matplotlib.image
    import numpy as np
    pixels = matplotlib.image.imread(png)
    return len(np.unique(pixels.reshape(-1, pixels.shape[-1]), axis=0))


def checks(numbers, prefix):
    """[(ok, text)] of -check."""
    out = [(numbers["isoPolygons"] > 0, "the Q iso-surface has %d polygons"
            % numbers["isoPolygons"]),
           (numbers["sliceCells"] > 0, "the plane has %d cells"
            % numbers["sliceCells"])]
    for png in (prefix + "-Q.png", prefix + "-mesh.png"):
        n = colours(png) if os.path.isfile(png) else 0
        out.append((n > 16, "%s: %d colours" % (png, n)))
    return out


def parse(argv):
    p = argparse.ArgumentParser(prog="flapfoam plot_flow",
                                description=__doc__.split("\n")[1])
    p.add_argument("run")
    p.add_argument("-time", type=float, help="default: the latest")
    p.add_argument("-q", type=float, default=1e5,
                   help="the Q level, 1/s^2 (default 1e5)")
    p.add_argument("-o", dest="prefix",
                   help="default RUN/plots/flow-<T>")
    p.add_argument("-check", action="store_true",
                   help="PASS/FAIL lines; exit 1 unless all pass")
    a = p.parse_args(argv)
    if not a.q > 0:
        p.error("-q %g: allowed a level > 0" % a.q)
    if not os.path.isdir(a.run):
        p.error("%s: no such run folder" % a.run)
    return a


def main(argv=None):
    a = parse(argv)
    run = os.path.abspath(a.run)
    time_name, case_type = pick_time(run, a.time)
    prefix = os.path.abspath(a.prefix or os.path.join(
        run, "plots", "flow-" + time_name))
    os.makedirs(os.path.dirname(prefix), exist_ok=True)
    numbers = render(run, time_name, case_type, a.q, prefix)
    numbers.update(run=run, caseType=case_type)
    with open(prefix + ".json", "w") as fh:
        json.dump(numbers, fh, indent=1)
    print("plot_flow: %s at t = %s (%s): Q = %g, %d polygons (largest Q "
          "%.3g), %d cells on the plane: %s-{Q,mesh}.png, .json"
          % (run, time_name, case_type.split()[0].lower(), a.q,
             numbers["isoPolygons"], numbers["qMax"], numbers["sliceCells"],
             prefix))
    if not a.check:
        return 0
    results = checks(numbers, prefix)
    for ok, text in results:
        print("%s plot_flow %s" % ("PASS" if ok else "FAIL", text))
    return 0 if all(ok for ok, _ in results) else 1


if __name__ == "__main__":
    sys.exit(run_tool(main))
