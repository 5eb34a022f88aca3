# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.checks.mpi_counts_checks on counts files written here: the probe's
as libflapFoamMPICounters.so writes them (passes), one byte off (fails),
and the per-step traffic of made-up runs."""

import pytest

from flapfoam.checks import mpi_counts_checks as mc

from mpi_counts_files import write_rank


def probe_files(folder, off=0):
    for r in (0, 1):
        functions = {k: (c, b + (off if (r, k) == (0, "MPI_Send") else 0),
                         d if d is not None else 0)
                     for k, (c, b, d) in mc.PROBE[r].items()}
        write_rank(folder, r, 2, functions, mc.PROBE_TO[r])


def run(argv, capsys):
    rc = mc.main(argv)
    return rc, capsys.readouterr().out.splitlines()


def test_the_probe_as_sent_passes_and_a_byte_off_fails(tmp_path, capsys):
    probe_files(tmp_path / "good")
    rc, out = run(["probe", str(tmp_path / "good")], capsys)
    assert rc == 0 and all(line.startswith("PASS") for line in out)
    assert len(out) == 5
    probe_files(tmp_path / "bad", off=1)
    rc, out = run(["probe", str(tmp_path / "bad")], capsys)
    assert rc == 1
    assert [line[:4] for line in out] == ["PASS", "FAIL", "PASS", "PASS",
                                          "PASS"]


def halo_run(folder, steps, faces=12):
    """Two ranks exchanging one halo of faces doubles a step with each
    other, one allreduce a step."""
    for r in (0, 1):
        write_rank(folder, r, 2,
                   {"MPI_Isend": (steps, 8*faces*steps, 1),
                    "MPI_Allreduce": (steps, 8*steps, None)},
                   {1 - r: (steps, 8*faces*steps)})


def test_steps_the_same_traffic_every_step(tmp_path, capsys):
    for n in (2, 4, 6):
        halo_run(tmp_path / ("n%d" % n), n)
    runs = ["%s:%d" % (tmp_path / ("n%d" % n), n) for n in (2, 4, 6)]
    rc, out = run(["steps", "12", "1"] + runs, capsys)
    assert rc == 0, out
    # another number of processor faces: the bytes are not whole halos
    rc, out = run(["steps", "7", "1"] + runs, capsys)
    assert rc == 1 and out[-1].startswith("FAIL")


def test_non_zero_and_bad_usage(tmp_path, capsys):
    halo_run(tmp_path / "r", 3)
    assert run(["nonZero", str(tmp_path / "r"), "cube"], capsys)[0] == 0
    with pytest.raises(SystemExit) as end:
        mc.main(["bogus"])
    assert end.value.code == 2
    assert "invalid choice: 'bogus'" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        mc.main(["steps", "4", "2", "only:1"])
    assert "at least two DIR:N" in capsys.readouterr().err
