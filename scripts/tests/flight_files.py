# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Flight data files as the flightData function object writes them, made
up for the tests of the readers of a run's flight data."""

import h5py


def write_run(case, rows, columns=None):
    """case/postProcessing/flightData/0/flightData.h5 holding the datasets
    rows {name: array}, with columns {name: "q_0 q_1 ..."} as the
    datasets' column names; the case folder (a str) back."""
    folder = case / "postProcessing" / "flightData" / "0"
    folder.mkdir(parents=True)
    with h5py.File(folder / "flightData.h5", "w") as f:
        for name, v in rows.items():
            f[name] = v
        for name, names in (columns or {}).items():
            f[name].attrs["columns"] = names
    return str(case)
