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

Description
    Unit tests of flightDataFile in a scratch folder, read back with the
    HDF5 library itself.

\*---------------------------------------------------------------------------*/

#include "flightDataFile.H"
#include "OSspecific.H"
#include "expectError.H"

#include <hdf5.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- A scratch folder /tmp/flapFoamTest-flightData-XXXXXX, removed after
struct scratch
{
    fileName dir;

    scratch()
    {
        std::string tmpl("/tmp/flapFoamTest-flightData-XXXXXX");
        if (!mkdtemp(&tmpl[0]))
        {
            std::abort();
        }
        dir = tmpl;
    }

    ~scratch()
    {
        rmDir(dir, true);
    }
};


//- A row at time t: the wing's force (x y z) and one joint q
flightDataFile::row row(const scalar t, const label nForce = 3)
{
    flightDataFile::row r;
    wordList columns({"x", "y", "z"});
    columns.setSize(nForce);
    scalarList force(nForce);
    forAll(force, i)
    {
        force[i] = 10*t + i;
    }
    r.append({"bodies/wing/force", columns, force});
    r.append({"joints/q", wordList({"q_0"}), scalarList({-t})});
    r.append({"time", wordList(), scalarList({t})});
    return r;
}


//- A file with the rows at times
void write(const fileName& path, std::initializer_list<scalar> times)
{
    flightDataFile f(path, 0);
    for (const scalar t : times)
    {
        f.append(row(t));
    }
}


//- A dataset's values (row major) and its rows and columns
std::vector<double> read
(
    const fileName& path,
    const std::string& name,
    hsize_t& nRows,
    hsize_t& nCols
)
{
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t ds = H5Dopen(file, name.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(ds);
    hsize_t dims[2] = {0, 1};
    H5Sget_simple_extent_dims(space, dims, nullptr);
    nRows = dims[0];
    nCols = H5Sget_simple_extent_ndims(space) == 2 ? dims[1] : 1;
    std::vector<double> values(nRows*nCols);
    H5Dread
    (
        ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()
    );
    H5Sclose(space);
    H5Dclose(ds);
    H5Fclose(file);
    return values;
}


//- The rows of a dataset
hsize_t rows(const fileName& path, const std::string& name)
{
    hsize_t nRows, nCols;
    read(path, name, nRows, nCols);
    return nRows;
}


//- A string attribute of an object of the file
std::string attribute
(
    const fileName& path,
    const std::string& object,
    const std::string& name
)
{
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t attr =
        H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT,
                        H5P_DEFAULT);
    const hid_t type = H5Aget_type(attr);
    char* value = nullptr;
    H5Aread(attr, type, &value);
    const std::string result(value ? value : "");
    H5free_memory(value);
    H5Tclose(type);
    H5Aclose(attr);
    H5Fclose(file);
    return result;
}


//- Add n rows to a dataset by hand (a killed run's half-written row)
void extend(const fileName& path, const std::string& name, const hsize_t n)
{
    hsize_t nRows, nCols;
    read(path, name, nRows, nCols);
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hid_t ds = H5Dopen(file, name.c_str(), H5P_DEFAULT);
    const hsize_t dims[2] = {nRows + n, nCols};
    H5Dset_extent(ds, dims);
    H5Dclose(ds);
    H5Fclose(file);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(flightDataFile, rowsReadBack)
{
    const scratch s;
    const fileName path(s.dir/"sub"/"flightData.h5");     // folder made
    {
        flightDataFile f(path, 0);
        EXPECT_EQ(f.nRows(), 0);
        f.append(row(0.1));
        f.append(row(0.2));
        f.setAttributes({{"case", "box"}, {"level", "tiny"}});
        EXPECT_EQ(f.nRows(), 2);
    }
    hsize_t nRows, nCols;
    EXPECT_EQ(read(path, "time", nRows, nCols), std::vector<double>({0.1, 0.2}));
    EXPECT_EQ(nCols, 1u);
    EXPECT_EQ
    (
        read(path, "bodies/wing/force", nRows, nCols),
        std::vector<double>({1, 2, 3, 2, 3, 4})
    );
    EXPECT_EQ(nRows, 2u);
    EXPECT_EQ(nCols, 3u);
    EXPECT_EQ(read(path, "joints/q", nRows, nCols),
              std::vector<double>({-0.1, -0.2}));
    EXPECT_EQ(nCols, 1u);
    EXPECT_EQ(attribute(path, "bodies/wing/force", "columns"), "x y z");
    EXPECT_EQ(attribute(path, "/", "case"), "box");
    EXPECT_EQ(attribute(path, "/", "level"), "tiny");
    EXPECT_EQ(flightDataFile::damage(path), "");
}


TEST(flightDataFile, restartKeepsTheRowsUpToItsTime)
{
    const scratch s;
    const fileName path(s.dir/"flightData.h5");
    write(path, {0.1, 0.2, 0.3});
    {
        flightDataFile f(path, 0.2);
        EXPECT_EQ(f.nRows(), 2);
        f.append(row(0.25));
    }
    hsize_t nRows, nCols;
    EXPECT_EQ(read(path, "time", nRows, nCols),
              std::vector<double>({0.1, 0.2, 0.25}));
    EXPECT_EQ(rows(path, "bodies/wing/force"), 3u);
    EXPECT_EQ(rows(path, "joints/q"), 3u);

    // A restart time a round-off below a row's keeps it
    flightDataFile again(path, 0.25*(1 - 1e-14));
    EXPECT_EQ(again.nRows(), 3);
}


TEST(flightDataFile, aHalfWrittenRowIsDroppedOnRestart)
{
    const scratch s;
    const fileName path(s.dir/"flightData.h5");
    write(path, {0.1, 0.2});
    // killed inside the third row: force written, time not
    extend(path, "bodies/wing/force", 1);
    EXPECT_EQ(flightDataFile::damage(path), "");
    {
        flightDataFile f(path, 1.0);
        EXPECT_EQ(f.nRows(), 2);
    }
    EXPECT_EQ(rows(path, "bodies/wing/force"), 2u);
    EXPECT_EQ(rows(path, "time"), 2u);
}


TEST(flightDataFile, damageNamesWhatIsWrong)
{
    const scratch s;
    const fileName path(s.dir/"flightData.h5");
    write(path, {0.1, 0.2});
    extend(path, "joints/q", 2);
    EXPECT_EQ
    (
        flightDataFile::damage(path),
        "dataset joints/q has 4 rows, time 2"
    );
    const fileName bad(s.dir/"bad.h5");
    std::ofstream(bad) << "not HDF5";
    EXPECT_EQ
    (
        flightDataFile::damage(bad),
        "not a readable HDF5 file (truncated or corrupt)"
    );
    expectIOError([&]{ flightDataFile(bad, 0); }, {"bad.h5", "HDF5"});
}


TEST(flightDataFile, badRows)
{
    const scratch s;
    const fileName path(s.dir/"flightData.h5");
    write(path, {0.1, 0.2});
    {
        flightDataFile f(path, 1.0);
        expectError
        (
            [&]{ f.append(row(0.3, 2)); },
            {"bodies/wing/force", "has 2 rows of 3 columns", "expected 2 of 2"}
        );
    }
    {
        // a restart that writes a dataset the run before did not
        flightDataFile f(path, 0.15);
        flightDataFile::row r(row(0.2));
        r.append({"bodies/lid/force", wordList({"x"}), scalarList({1})});
        expectError
        (
            [&]{ f.append(r); },
            {"bodies/lid/force is not in", "the same datasets as the run"}
        );
    }
}


// ************************************************************************* //
