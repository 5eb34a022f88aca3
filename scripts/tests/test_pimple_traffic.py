# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.bench.pimple_traffic on made-up runs: two settings of two
ranks, runs of 2 and 5 steps (counts files and solver logs): one step's
messages, bytes and collectives, the pressure iterations of steps 3 to 5
and their ratios; a setting with one run only is left out, none refused."""

import pytest

from flapfoam.bench import pimple_traffic as pt
from flapfoam.errors import FlapFoamError
from mpi_counts_files import write_rank

LOG = """Time = {t}
DILUPBiCGStab:  Solving for p, Initial residual = 1, Final residual = 1e-07, No Iterations {n}
DILUPBiCGStab:  Solving for p, Initial residual = 1, Final residual = 1e-07, No Iterations {n}
ExecutionTime = {t} s  ClockTime = 1 s
"""


def run(folder, steps, halo, reductions, iterations):
    """Two ranks, each step: halo messages of 80 bytes to the other rank
    and reductions allreduces; the log's p solves of iterations each (2
    solves a step); one message and one reduction at the start."""
    for r in (0, 1):
        write_rank(folder / "counts", r, 2,
                   {"MPI_Isend": (1 + halo*steps, 80*(1 + halo*steps), 1),
                    "MPI_Allreduce": (1 + reductions*steps,
                                      8*(1 + reductions*steps), None)},
                   {1 - r: (1 + halo*steps, 80*(1 + halo*steps))})
    (folder / "log.overPimpleDyMFoam").write_text("".join(
        LOG.format(t=k + 1, n=iterations[k]) for k in range(steps)))


def study(tmp_path):
    for s in (2, 5):
        run(tmp_path / ("tiny-np2-defaults-s%d" % s), s, 40, 60,
            [9, 9, 10, 10, 10])
        run(tmp_path / ("tiny-np2-gamg-s%d" % s), s, 90, 12, [3, 3, 2, 2, 2])
    run(tmp_path / "tiny-np2-lonely-s2", 2, 1, 1, [1, 1])
    return tmp_path


def test_one_step_per_rank(tmp_path):
    rows = {r.setting: r for r in pt.read_folder(str(study(tmp_path)), 2, 5)}
    assert sorted(rows) == ["defaults", "gamg"]
    d, g = rows["defaults"], rows["gamg"]
    assert (d.messages, d.collectives) == ((40, 40), 60)
    assert d.kbytes == (3.2, 3.2)
    assert d.p_iterations == 20     # steps 3-5: 2 solves of 10
    assert g.p_iterations == 4
    assert d.per_iteration(d.collectives) == 3
    assert g.per_iteration(g.messages[0]) == 22.5


def test_table_and_output(tmp_path, capsys):
    out = tmp_path / "t.md"
    assert pt.main([str(study(tmp_path)), "-count", "2", "5",
                    "-o", str(out)]) == 0
    text = out.read_text()
    assert "| tiny | 2 | defaults | 20.0 | 40 | 40 | 3.2 | 3.2 | 60 | 2.0 " \
           "| 3.0 |" in text
    assert text == capsys.readouterr().out


@pytest.mark.parametrize("count, message", [
    (("5", "2"), "two step counts 0 < N1 < N2"),
    (("2", "4"), "no runs <level>-np<N>-<setting>-s2 and -s4"),
])
def test_refused(tmp_path, count, message):
    with pytest.raises(FlapFoamError, match=message.replace("<", ".")):
        pt.main([str(study(tmp_path)), "-count"] + list(count))


def test_short_log_refused(tmp_path):
    folder = study(tmp_path)
    (folder / "tiny-np2-gamg-s5" / "log.overPimpleDyMFoam").write_text(
        LOG.format(t=1, n=1))
    with pytest.raises(FlapFoamError, match="1 steps in its solver log, 5"):
        pt.read_folder(str(folder), 2, 5)
