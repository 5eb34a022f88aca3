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
\*---------------------------------------------------------------------------*/

#include "flightDataFile.H"
#include "OSspecific.H"
#include "error.H"

#include <hdf5.h>

// HDF5's macros (H5S_ALL, H5T_VARIABLE, ...) are C casts
#pragma GCC diagnostic ignored "-Wold-style-cast"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- An HDF5 handle, closed when it goes out of scope
class handle
{
    hid_t id_;
    herr_t (*close_)(hid_t);

public:

    handle(const hid_t id, herr_t (*close)(hid_t))
    :
        id_(id),
        close_(close)
    {}

    ~handle()
    {
        if (id_ >= 0)
        {
            close_(id_);
        }
    }

    handle(const handle&) = delete;
    void operator=(const handle&) = delete;

    operator hid_t() const
    {
        return id_;
    }

};


//- FatalIOError naming the file and what failed if status < 0 (an IO
//- error: a function object's constructor that raises it stops the run,
//- where v1912's functionObjectList turns a FatalError into a warning)
void check(const long status, const fileName& path, const std::string& what)
{
    if (status < 0)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, path)
            << "HDF5: " << what.c_str() << " failed for " << path
            << exit(FatalIOError);
    }
}


//- Make a folder, else FatalIOError naming it (OpenFOAM's mkDir raises a
//- FatalError, which a function object's constructor turns into a warning)
void makeFolder(const fileName& dir)
{
    const bool throwing = FatalError.throwExceptions();
    bool made = false;
    string why("no permission?");
    try
    {
        made = mkDir(dir);
    }
    catch (const Foam::error& err)
    {
        why = err.message();
    }
    FatalError.throwExceptions(throwing);

    if (!made)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, dir)
            << "Cannot create the folder " << dir.c_str() << " of the flight"
            << " data: " << why.c_str() << nl << "Move away what is in the"
            << " way or make it writable; the run does not start without"
            << " its flight data" << exit(FatalIOError);
    }
}


//- The paths of the datasets of a file (H5Ovisit)
herr_t collectDatasets
(
    hid_t,
    const char* name,
    const H5O_info_t* info,
    void* data
)
{
    if (info->type == H5O_TYPE_DATASET)
    {
        static_cast<DynamicList<word>*>(data)->append(word(name, false));
    }
    return 0;
}


//- Write a string attribute (variable length, UTF-8) of an object,
//- replacing one of the same name
void writeAttribute
(
    const hid_t obj,
    const word& name,
    const std::string& value,
    const fileName& path
)
{
    if (H5Aexists(obj, name.c_str()) > 0)
    {
        H5Adelete(obj, name.c_str());
    }
    handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    handle space(H5Screate(H5S_SCALAR), H5Sclose);
    handle attr
    (
        H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose
    );
    check(attr, path, "create attribute " + name);
    const char* cValue = value.c_str();
    check(H5Awrite(attr, type, &cValue), path, "write attribute " + name);
}


//- Create the chunked dataset of an entry, extendable along the rows, with
//- its column names
void createDataset
(
    const hid_t file,
    const hid_t lcpl,
    const flightDataFile::entry& e,
    const fileName& path
)
{
    const int rank = e.columns.empty() ? 1 : 2;
    const hsize_t nCols = e.columns.empty() ? 1 : e.columns.size();
    const hsize_t dims[2] = {0, nCols};
    const hsize_t maxDims[2] = {H5S_UNLIMITED, nCols};
    const hsize_t chunk[2] = {256, nCols};
    handle space(H5Screate_simple(rank, dims, maxDims), H5Sclose);
    handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    H5Pset_chunk(dcpl, rank, chunk);
    handle ds
    (
        H5Dcreate2
        (
            file, e.name.c_str(), H5T_IEEE_F64LE, space, lcpl, dcpl,
            H5P_DEFAULT
        ),
        H5Dclose
    );
    check(ds, path, "create dataset " + e.name);

    if (e.columns.size())
    {
        string columns;
        for (const word& c : e.columns)
        {
            columns += (columns.empty() ? "" : " ") + c;
        }
        writeAttribute(ds, "columns", columns, path);
    }
}


//- Append the values of an entry as row nRows of its dataset (FatalError
//- if the dataset has another number of rows or columns)
void writeRow
(
    const hid_t file,
    const flightDataFile::entry& e,
    const label nRows,
    const fileName& path
)
{
    const int rank = e.columns.empty() ? 1 : 2;
    const hsize_t nCols = e.columns.empty() ? 1 : e.columns.size();

    handle ds(H5Dopen(file, e.name.c_str(), H5P_DEFAULT), H5Dclose);
    check(ds, path, "open dataset " + e.name);

    {
        handle space(H5Dget_space(ds), H5Sclose);
        hsize_t dims[2] = {0, 0};
        H5Sget_simple_extent_dims(space, dims, nullptr);
        if
        (
            H5Sget_simple_extent_ndims(space) != rank
         || label(dims[0]) != nRows
         || (rank == 2 && dims[1] != nCols)
        )
        {
            FatalErrorInFunction
                << "dataset " << e.name << " of " << path << " has "
                << label(dims[0]) << " rows of "
                << label(rank == 2 ? dims[1] : 1) << " columns; expected "
                << nRows << " of " << label(nCols)
                << exit(FatalError);
        }
    }

    const hsize_t newDims[2] = {hsize_t(nRows + 1), nCols};
    check(H5Dset_extent(ds, newDims), path, "extend " + e.name);

    handle fileSpace(H5Dget_space(ds), H5Sclose);
    const hsize_t start[2] = {hsize_t(nRows), 0};
    const hsize_t count[2] = {1, nCols};
    H5Sselect_hyperslab
    (
        fileSpace, H5S_SELECT_SET, start, nullptr, count, nullptr
    );
    handle memSpace(H5Screate_simple(rank, count, nullptr), H5Sclose);
    check
    (
        H5Dwrite
        (
            ds, H5T_NATIVE_DOUBLE, memSpace, fileSpace, H5P_DEFAULT,
            e.values.cdata()
        ),
        path,
        "write a row of " + e.name
    );
}


//- File access without HDF5's file locks: a reader of the flight data
//- during the run (h5py, a plot of the progress) holds a shared lock that
//- makes a locking writer's open fail, which would stop the run.  The file
//- is closed between steps, so a reader sees whole rows but for the one
//- being written.
struct unlockedAccess
{
    handle fapl;

    unlockedAccess()
    :
        fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose)
    {
        H5Pset_file_locking(fapl, false, true);
    }
};


//- Open a file read-write (errors of the library silenced: ours name the
//- file), without file locks
hid_t openFile(const fileName& path)
{
    H5Eset_auto(H5E_DEFAULT, nullptr, nullptr);
    const unlockedAccess access;
    return H5Fopen(path.c_str(), H5F_ACC_RDWR, access.fapl);
}


//- The times of a file's time dataset
scalarList readTimes(const hid_t file, const fileName& path)
{
    if (H5Lexists(file, "time", H5P_DEFAULT) <= 0)
    {
        return scalarList();
    }
    handle ds(H5Dopen(file, "time", H5P_DEFAULT), H5Dclose);
    check(ds, path, "open dataset time");
    handle space(H5Dget_space(ds), H5Sclose);
    hsize_t dims[2] = {0, 0};
    H5Sget_simple_extent_dims(space, dims, nullptr);
    scalarList times(static_cast<label>(dims[0]));
    if (times.size())
    {
        check
        (
            H5Dread
            (
                ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                times.data()
            ),
            path,
            "read dataset time"
        );
    }
    return times;
}


//- The rows of a dataset (-1 if it cannot be opened)
label datasetRows(const hid_t file, const word& name)
{
    handle ds(H5Dopen(file, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (ds < 0)
    {
        return -1;
    }
    handle space(H5Dget_space(ds), H5Sclose);
    hsize_t dims[2] = {0, 0};
    return
        space >= 0 && H5Sget_simple_extent_dims(space, dims, nullptr) >= 0
      ? label(dims[0])
      : -1;
}

//- Write e's values as row nRows of its dataset (made on the first row)
//- in the open file
void appendEntry
(
    const hid_t file,
    const hid_t lcpl,
    const flightDataFile::entry& e,
    const label nRows,
    const fileName& path
)
{
    const label nCols = e.columns.empty() ? 1 : e.columns.size();

    if (nCols != e.values.size())
    {
        FatalErrorInFunction
            << "dataset " << e.name << " of " << path << ": "
            << e.values.size() << " values for " << nCols
            << " columns"
            << abort(FatalError);
    }

    if (H5Lexists(file, e.name.c_str(), H5P_DEFAULT) <= 0)
    {
        if (nRows)
        {
            FatalErrorInFunction
                << "dataset " << e.name << " is not in " << path
                << " (" << nRows << " rows): a restart must write the"
                << " same datasets as the run before" << exit(FatalError);
        }
        createDataset(file, lcpl, e, path);
    }

    writeRow(file, e, nRows, path);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

Foam::string Foam::flightDataFile::damage(const fileName& path)
{
    H5Eset_auto(H5E_DEFAULT, nullptr, nullptr);
    const unlockedAccess access;
    handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.fapl), H5Fclose);
    if (file < 0)
    {
        return "not a readable HDF5 file (truncated or corrupt)";
    }

    DynamicList<word> datasets;
    if
    (
        H5Ovisit
        (
            file, H5_INDEX_NAME, H5_ITER_INC, collectDatasets, &datasets
        ) < 0
    )
    {
        return "its datasets cannot be listed";
    }

    // Every dataset has as many rows as time, or one more (a row a killed
    // run left half written: time is written last)
    const label nTimes = datasets.found("time") ? datasetRows(file, "time") : 0;
    for (const word& name : datasets)
    {
        const label n = datasetRows(file, name);
        if (n != nTimes && n != nTimes + 1)
        {
            return
                "dataset " + name + " has " + Foam::name(n) + " rows, time "
              + Foam::name(nTimes);
        }
    }
    if (nTimes > 0)
    {
        // The times themselves are readable
        scalarList times(nTimes);
        handle ds(H5Dopen(file, "time", H5P_DEFAULT), H5Dclose);
        if
        (
            H5Dread
            (
                ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                times.data()
            ) < 0
        )
        {
            return "its dataset time cannot be read";
        }
    }

    return string();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::flightDataFile::flightDataFile
(
    const fileName& path,
    const scalar restartTime
)
:
    path_(path),
    nRows_(0)
{
    if (isFile(path_))
    {
        handle file(openFile(path_), H5Fclose);
        check(file, path_, "open (is it an HDF5 file?)");

        // Keep the rows up to the restart time, as long as the times
        // increase
        const scalarList times(readTimes(file, path_));
        const scalar tol = 1e-12*max(mag(restartTime), VSMALL);
        while
        (
            nRows_ < times.size() && times[nRows_] <= restartTime + tol
         && (nRows_ == 0 || times[nRows_] > times[nRows_ - 1])
        )
        {
            ++nRows_;
        }

        // Every dataset cut to them (with the rows after the restart time,
        // a row a killed run left half written)
        DynamicList<word> datasets;
        check
        (
            H5Ovisit
            (
                file, H5_INDEX_NAME, H5_ITER_INC, collectDatasets, &datasets
            ),
            path_,
            "list the datasets"
        );
        for (const word& name : datasets)
        {
            handle ds(H5Dopen(file, name.c_str(), H5P_DEFAULT), H5Dclose);
            check(ds, path_, "open dataset " + name);
            handle space(H5Dget_space(ds), H5Sclose);
            hsize_t dims[2] = {0, 0};
            H5Sget_simple_extent_dims(space, dims, nullptr);
            if (label(dims[0]) > nRows_)
            {
                dims[0] = nRows_;
                check
                (
                    H5Dset_extent(ds, dims), path_, "cut dataset " + name
                );
            }
        }
    }
    else
    {
        makeFolder(path_.path());
        const unlockedAccess access;
        handle file
        (
            H5Fcreate(path_.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, access.fapl),
            H5Fclose
        );
        check(file, path_, "create");
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::flightDataFile::setAttributes
(
    const List<Tuple2<word, string>>& attributes
) const
{
    handle file(openFile(path_), H5Fclose);
    check(file, path_, "open");

    for (const Tuple2<word, string>& a : attributes)
    {
        writeAttribute(file, a.first(), a.second(), path_);
    }
}


void Foam::flightDataFile::append(const row& r)
{
    handle file(openFile(path_), H5Fclose);
    check(file, path_, "open");

    handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    H5Pset_create_intermediate_group(lcpl, 1);

    // time written last, after the others are flushed to the file: a kill
    // inside the write leaves the other datasets at most one row longer
    // than time, never time longer than them
    const entry* time = nullptr;
    for (const entry& e : r)
    {
        if (e.name == "time")
        {
            time = &e;
        }
        else
        {
            appendEntry(file, lcpl, e, nRows_, path_);
        }
    }
    if (!time)
    {
        FatalErrorInFunction
            << "a row of " << path_ << " without dataset time"
            << abort(FatalError);
    }
    check(H5Fflush(file, H5F_SCOPE_LOCAL), path_, "flush");
    appendEntry(file, lcpl, *time, nRows_, path_);

    ++nRows_;
}


// ************************************************************************* //
