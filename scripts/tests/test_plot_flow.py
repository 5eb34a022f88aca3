# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.plots.flow (plot_flow): which time of a run is rendered, and
how (reconstructed or decomposed); the run's .foam file; bad options.  The
render itself (pvbatch) is checked on a CFD run by cases/twoWingDrone's
Alltest."""

import pytest

from flapfoam.errors import FlapFoamError
from flapfoam.plots import flow


def make_run(tmp_path, root=(), decomposed=()):
    """A run folder whose time folders root (reconstructed) and
    decomposed (processor0/) hold U; 'empty' times hold nothing."""
    for t in root:
        (tmp_path / t).mkdir(parents=True)
        (tmp_path / t / "U").write_text("")
    for t in decomposed:
        (tmp_path / "processor0" / t).mkdir(parents=True)
        (tmp_path / "processor0" / t / "U").write_text("")
    (tmp_path / "constant").mkdir(parents=True, exist_ok=True)
    (tmp_path / "0.5").mkdir()          # a time without U: not written
    return str(tmp_path)


def test_the_latest_time_reconstructed_where_it_is(tmp_path):
    run = make_run(tmp_path, root=["0", "0.1"], decomposed=["0.1", "0.2"])
    assert flow.pick_time(run, None) == ("0.2", "Decomposed Case")
    assert flow.pick_time(run, 0.1) == ("0.1", "Reconstructed Case")
    assert flow.pick_time(run, 0) == ("0", "Reconstructed Case")


def test_a_time_not_written_names_the_written_ones(tmp_path):
    run = make_run(tmp_path, root=["0", "0.1"])
    with pytest.raises(FlapFoamError, match=r"-time 0.5: not a written time"
                       r".*\(written: 0 0.1\)"):
        flow.pick_time(run, 0.5)
    with pytest.raises(FlapFoamError, match="no time folder with a field U"):
        flow.pick_time(make_run(tmp_path / "empty"), None)


def test_foam_file_is_the_runs_or_made(tmp_path):
    run = make_run(tmp_path / "myRun", root=["0"])
    made = flow.foam_file(run)
    assert made.endswith("myRun/myRun.foam")
    assert flow.foam_file(run) == made


def test_bad_options_are_refused(tmp_path, capsys):
    with pytest.raises(SystemExit):
        flow.parse([str(tmp_path), "-q", "0"])
    assert "-q 0: allowed a level > 0" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        flow.parse([str(tmp_path / "none")])
    assert "no such run folder" in capsys.readouterr().err


def test_checks_pass_and_fail(tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    fig = plt.figure()
    plt.imshow(np.arange(400).reshape(20, 20))
    fig.savefig(str(tmp_path / "p-Q.png"))
    plt.close(fig)
    results = flow.checks({"isoPolygons": 0, "sliceCells": 5},
                          str(tmp_path / "p"))
    assert [ok for ok, _ in results] == [False, True, True, False]
    assert "0 colours" in results[3][1]
