/*---------------------------------------------------------------------------*\
  flapFoam: free-flight simulation of flapping-wing drones on OpenFOAM v1912
-------------------------------------------------------------------------------
    Copyright (C) 2025-2026 flapFoam developers
-------------------------------------------------------------------------------
License
    This file is part of flapFoam, derived from OpenFOAM.

    flapFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    flapFoam is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with flapFoam (COPYING).  If not, see <http://www.gnu.org/licenses/>.

Application
    flapFoamTest-flightData

Description
    GoogleTest unit tests of libflapFoamFlightData (Test-<class>.C):
      - flightDataFile: rows appended and read back with the HDF5 library
        (values, shapes, the columns attribute, the root's attributes); a
        restart keeps the rows up to its time and cuts every dataset to
        them, a row a killed run left half written included; damage()
        accepts that row and names a file that is not HDF5 or a dataset
        of other rows; a row of other columns, or a restart without a
        dataset of the run before, stops with an error naming them.
    The function object on solver runs (restart, kill -9, parallel) is in
    the drone cases' Alltest.

\*---------------------------------------------------------------------------*/

#include "throwingTestMain.H"


// ************************************************************************* //
