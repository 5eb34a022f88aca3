#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Read and check the flight data (HDF5) of a drone run: flapfoam.flight_data
(usage there)."""

import sys

from flapfoam.flight_data import main

if __name__ == "__main__":
    sys.exit(main())
