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

#include "mpiCounters.H"
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <sys/stat.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const char* const Foam::mpiCounters::names[nFunctions] =
{
    "MPI_Send", "MPI_Bsend", "MPI_Ssend", "MPI_Rsend", "MPI_Isend",
    "MPI_Ibsend", "MPI_Issend", "MPI_Irsend",
    "MPI_Sendrecv", "MPI_Sendrecv_replace",
    "MPI_Barrier", "MPI_Bcast", "MPI_Reduce", "MPI_Allreduce", "MPI_Gather",
    "MPI_Gatherv", "MPI_Scatter", "MPI_Scatterv", "MPI_Allgather",
    "MPI_Allgatherv", "MPI_Alltoall", "MPI_Alltoallv"
};


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

int Foam::mpiCounters::worldRank(int dest, MPI_Comm comm)
{
    if (comm == MPI_COMM_WORLD)
    {
        return dest;
    }

    // dest is a rank of the remote group of an intercommunicator
    int inter = 0;
    PMPI_Comm_test_inter(comm, &inter);
    MPI_Group group, world;
    if (inter)
    {
        PMPI_Comm_remote_group(comm, &group);
    }
    else
    {
        PMPI_Comm_group(comm, &group);
    }
    PMPI_Comm_group(MPI_COMM_WORLD, &world);

    int w = MPI_UNDEFINED;
    PMPI_Group_translate_ranks(group, 1, &dest, world, &w);
    PMPI_Group_free(&group);
    PMPI_Group_free(&world);
    return w;
}


int Foam::mpiCounters::nDestinations(function f) const
{
    int n = 0;
    for (int w = 0; w < nWorld_; ++w)
    {
        n += callsTo_[f*nWorld_ + w] > 0;
    }
    return n;
}


std::int64_t Foam::mpiCounters::callsTo(int w) const
{
    std::int64_t n = 0;
    for (int f = 0; f < firstCollective; ++f)
    {
        n += callsTo_[f*nWorld_ + w];
    }
    return n;
}


std::string Foam::mpiCounters::text(int rank) const
{
    std::ostringstream os;
    os  << "# flapFoam MPI counts (libflapFoamMPICounters.so, see"
        << " src/mpiCounters/mpiCounters.H)\n"
        << "# bytes: point-to-point the message, collectives this rank's"
        << " contribution\n"
        << "rank " << rank << '\n'
        << "nRanks " << size(MPI_COMM_WORLD) << '\n'
        << "# function kind calls bytes destinations\n";

    for (int f = 0; f < nFunctions; ++f)
    {
        const bool p2p = f < firstCollective;
        os  << names[f] << (p2p ? " p2p " : " collective ")
            << calls_[f] << ' ' << bytes_[f] << ' ';
        if (p2p)
        {
            os  << nDestinations(function(f)) << '\n';
        }
        else
        {
            os  << "-\n";
        }
    }

    os  << "# to rank calls bytes\n";
    for (int w = 0; w < nWorld_; ++w)
    {
        if (callsTo(w))
        {
            os  << "to " << w << ' ' << callsTo(w) << ' ' << bytesTo_[w]
                << '\n';
        }
    }
    return os.str();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpiCounters::mpiCounters()
:
    calls_(nFunctions, 0),
    bytes_(nFunctions, 0),
    callsTo_(),
    bytesTo_(),
    nWorld_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::mpiCounters& Foam::mpiCounters::counters()
{
    static mpiCounters c;
    return c;
}


std::int64_t Foam::mpiCounters::bytes(int count, MPI_Datatype type)
{
    int typeSize = 0;
    PMPI_Type_size(type, &typeSize);
    return std::int64_t(count)*typeSize;
}


std::int64_t Foam::mpiCounters::bytes
(
    const int counts[],
    int nBlocks,
    MPI_Datatype type
)
{
    std::int64_t n = 0;
    for (int i = 0; i < nBlocks; ++i)
    {
        n += counts[i];
    }
    int typeSize = 0;
    PMPI_Type_size(type, &typeSize);
    return n*typeSize;
}


int Foam::mpiCounters::size(MPI_Comm comm)
{
    int n = 0;
    PMPI_Comm_size(comm, &n);
    return n;
}


int Foam::mpiCounters::rank(MPI_Comm comm)
{
    int r = 0;
    PMPI_Comm_rank(comm, &r);
    return r;
}


void Foam::mpiCounters::send
(
    function f,
    int count,
    MPI_Datatype type,
    int dest,
    MPI_Comm comm
)
{
    ++calls_[f];
    if (dest == MPI_PROC_NULL)
    {
        return;
    }
    const std::int64_t n = bytes(count, type);
    bytes_[f] += n;

    if (!nWorld_)
    {
        nWorld_ = size(MPI_COMM_WORLD);
        callsTo_.assign(firstCollective*nWorld_, 0);
        bytesTo_.assign(nWorld_, 0);
    }
    const int w = worldRank(dest, comm);
    if (w >= 0 && w < nWorld_)
    {
        ++callsTo_[f*nWorld_ + w];
        bytesTo_[w] += n;
    }
}


void Foam::mpiCounters::collective(function f, std::int64_t nBytes)
{
    ++calls_[f];
    bytes_[f] += nBytes;
}


void Foam::mpiCounters::write() const
{
    const char* dir = std::getenv("FLAPFOAM_MPI_COUNTS");
    if (!dir || !*dir)
    {
        return;
    }

    const int r = rank(MPI_COMM_WORLD);
    const std::string file = std::string(dir) + "/rank" + std::to_string(r);
    const std::string contents = text(r);

    // Every rank makes the folder: EEXIST is no error
    const bool made = mkdir(dir, 0777) == 0 || errno == EEXIST;
    std::FILE* fp = made ? std::fopen(file.c_str(), "w") : nullptr;
    const bool ok =
        fp
     && std::fwrite(contents.data(), 1, contents.size(), fp)
     == contents.size();
    if ((fp && std::fclose(fp) != 0) || !ok)
    {
        std::fprintf
        (
            stderr,
            "libflapFoamMPICounters: cannot write the counts of rank %d to"
            " %s (FLAPFOAM_MPI_COUNTS=%s): %s\n",
            r, file.c_str(), dir, std::strerror(errno)
        );
    }
}


// ************************************************************************* //
