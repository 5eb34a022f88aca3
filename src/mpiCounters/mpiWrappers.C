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
    The MPI functions of libflapFoamMPICounters.so: each counts its call in
    Foam::mpiCounters (which defines the bytes of each) and calls the real
    one through the profiling interface (PMPI_...).  MPI_Finalize writes
    the counts first.

\*---------------------------------------------------------------------------*/

#include "mpiCounters.H"

using Foam::mpiCounters;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

mpiCounters& counts()
{
    return mpiCounters::counters();
}

bool isRoot(int root, MPI_Comm comm)
{
    return mpiCounters::rank(comm) == root;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Point-to-point  * * * * * * * * * * * * * * //

extern "C"
{

int MPI_Send
(
    const void* buf, int count, MPI_Datatype type, int dest, int tag,
    MPI_Comm comm
)
{
    counts().send(mpiCounters::Send, count, type, dest, comm);
    return PMPI_Send(buf, count, type, dest, tag, comm);
}


int MPI_Bsend
(
    const void* buf, int count, MPI_Datatype type, int dest, int tag,
    MPI_Comm comm
)
{
    counts().send(mpiCounters::Bsend, count, type, dest, comm);
    return PMPI_Bsend(buf, count, type, dest, tag, comm);
}


int MPI_Ssend
(
    const void* buf, int count, MPI_Datatype type, int dest, int tag,
    MPI_Comm comm
)
{
    counts().send(mpiCounters::Ssend, count, type, dest, comm);
    return PMPI_Ssend(buf, count, type, dest, tag, comm);
}


int MPI_Rsend
(
    const void* buf, int count, MPI_Datatype type, int dest, int tag,
    MPI_Comm comm
)
{
    counts().send(mpiCounters::Rsend, count, type, dest, comm);
    return PMPI_Rsend(buf, count, type, dest, tag, comm);
}


int MPI_Isend
(
    const void* buf, int count, MPI_Datatype type, int dest, int tag,
    MPI_Comm comm, MPI_Request* request
)
{
    counts().send(mpiCounters::Isend, count, type, dest, comm);
    return PMPI_Isend(buf, count, type, dest, tag, comm, request);
}


int MPI_Ibsend
(
    const void* buf, int count, MPI_Datatype type, int dest, int tag,
    MPI_Comm comm, MPI_Request* request
)
{
    counts().send(mpiCounters::Ibsend, count, type, dest, comm);
    return PMPI_Ibsend(buf, count, type, dest, tag, comm, request);
}


int MPI_Issend
(
    const void* buf, int count, MPI_Datatype type, int dest, int tag,
    MPI_Comm comm, MPI_Request* request
)
{
    counts().send(mpiCounters::Issend, count, type, dest, comm);
    return PMPI_Issend(buf, count, type, dest, tag, comm, request);
}


int MPI_Irsend
(
    const void* buf, int count, MPI_Datatype type, int dest, int tag,
    MPI_Comm comm, MPI_Request* request
)
{
    counts().send(mpiCounters::Irsend, count, type, dest, comm);
    return PMPI_Irsend(buf, count, type, dest, tag, comm, request);
}


int MPI_Sendrecv
(
    const void* sendbuf, int sendcount, MPI_Datatype sendtype, int dest,
    int sendtag, void* recvbuf, int recvcount, MPI_Datatype recvtype,
    int source, int recvtag, MPI_Comm comm, MPI_Status* status
)
{
    counts().send(mpiCounters::Sendrecv, sendcount, sendtype, dest, comm);
    return PMPI_Sendrecv
    (
        sendbuf, sendcount, sendtype, dest, sendtag,
        recvbuf, recvcount, recvtype, source, recvtag, comm, status
    );
}


int MPI_Sendrecv_replace
(
    void* buf, int count, MPI_Datatype type, int dest, int sendtag,
    int source, int recvtag, MPI_Comm comm, MPI_Status* status
)
{
    counts().send(mpiCounters::Sendrecv_replace, count, type, dest, comm);
    return PMPI_Sendrecv_replace
    (
        buf, count, type, dest, sendtag, source, recvtag, comm, status
    );
}


// * * * * * * * * * * * * * * * * Collectives * * * * * * * * * * * * * * * //

int MPI_Barrier(MPI_Comm comm)
{
    counts().collective(mpiCounters::Barrier, 0);
    return PMPI_Barrier(comm);
}


int MPI_Bcast
(
    void* buf, int count, MPI_Datatype type, int root, MPI_Comm comm
)
{
    counts().collective
    (
        mpiCounters::Bcast,
        isRoot(root, comm) ? mpiCounters::bytes(count, type) : 0
    );
    return PMPI_Bcast(buf, count, type, root, comm);
}


int MPI_Reduce
(
    const void* sendbuf, void* recvbuf, int count, MPI_Datatype type,
    MPI_Op op, int root, MPI_Comm comm
)
{
    counts().collective(mpiCounters::Reduce, mpiCounters::bytes(count, type));
    return PMPI_Reduce(sendbuf, recvbuf, count, type, op, root, comm);
}


int MPI_Allreduce
(
    const void* sendbuf, void* recvbuf, int count, MPI_Datatype type,
    MPI_Op op, MPI_Comm comm
)
{
    counts().collective
    (
        mpiCounters::Allreduce,
        mpiCounters::bytes(count, type)
    );
    return PMPI_Allreduce(sendbuf, recvbuf, count, type, op, comm);
}


int MPI_Gather
(
    const void* sendbuf, int sendcount, MPI_Datatype sendtype,
    void* recvbuf, int recvcount, MPI_Datatype recvtype, int root,
    MPI_Comm comm
)
{
    counts().collective
    (
        mpiCounters::Gather,
        sendbuf == MPI_IN_PLACE
      ? mpiCounters::bytes(recvcount, recvtype)
      : mpiCounters::bytes(sendcount, sendtype)
    );
    return PMPI_Gather
    (
        sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, root,
        comm
    );
}


int MPI_Gatherv
(
    const void* sendbuf, int sendcount, MPI_Datatype sendtype,
    void* recvbuf, const int recvcounts[], const int displs[],
    MPI_Datatype recvtype, int root, MPI_Comm comm
)
{
    counts().collective
    (
        mpiCounters::Gatherv,
        sendbuf == MPI_IN_PLACE
      ? mpiCounters::bytes(recvcounts[root], recvtype)
      : mpiCounters::bytes(sendcount, sendtype)
    );
    return PMPI_Gatherv
    (
        sendbuf, sendcount, sendtype, recvbuf, recvcounts, displs,
        recvtype, root, comm
    );
}


int MPI_Scatter
(
    const void* sendbuf, int sendcount, MPI_Datatype sendtype,
    void* recvbuf, int recvcount, MPI_Datatype recvtype, int root,
    MPI_Comm comm
)
{
    counts().collective
    (
        mpiCounters::Scatter,
        isRoot(root, comm)
      ? mpiCounters::bytes(sendcount, sendtype)*mpiCounters::size(comm)
      : 0
    );
    return PMPI_Scatter
    (
        sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, root,
        comm
    );
}


int MPI_Scatterv
(
    const void* sendbuf, const int sendcounts[], const int displs[],
    MPI_Datatype sendtype, void* recvbuf, int recvcount,
    MPI_Datatype recvtype, int root, MPI_Comm comm
)
{
    counts().collective
    (
        mpiCounters::Scatterv,
        isRoot(root, comm)
      ? mpiCounters::bytes(sendcounts, mpiCounters::size(comm), sendtype)
      : 0
    );
    return PMPI_Scatterv
    (
        sendbuf, sendcounts, displs, sendtype, recvbuf, recvcount,
        recvtype, root, comm
    );
}


int MPI_Allgather
(
    const void* sendbuf, int sendcount, MPI_Datatype sendtype,
    void* recvbuf, int recvcount, MPI_Datatype recvtype, MPI_Comm comm
)
{
    counts().collective
    (
        mpiCounters::Allgather,
        sendbuf == MPI_IN_PLACE
      ? mpiCounters::bytes(recvcount, recvtype)
      : mpiCounters::bytes(sendcount, sendtype)
    );
    return PMPI_Allgather
    (
        sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, comm
    );
}


int MPI_Allgatherv
(
    const void* sendbuf, int sendcount, MPI_Datatype sendtype,
    void* recvbuf, const int recvcounts[], const int displs[],
    MPI_Datatype recvtype, MPI_Comm comm
)
{
    counts().collective
    (
        mpiCounters::Allgatherv,
        sendbuf == MPI_IN_PLACE
      ? mpiCounters::bytes(recvcounts[mpiCounters::rank(comm)], recvtype)
      : mpiCounters::bytes(sendcount, sendtype)
    );
    return PMPI_Allgatherv
    (
        sendbuf, sendcount, sendtype, recvbuf, recvcounts, displs,
        recvtype, comm
    );
}


int MPI_Alltoall
(
    const void* sendbuf, int sendcount, MPI_Datatype sendtype,
    void* recvbuf, int recvcount, MPI_Datatype recvtype, MPI_Comm comm
)
{
    counts().collective
    (
        mpiCounters::Alltoall,
        mpiCounters::size(comm)
       *(
            sendbuf == MPI_IN_PLACE
          ? mpiCounters::bytes(recvcount, recvtype)
          : mpiCounters::bytes(sendcount, sendtype)
        )
    );
    return PMPI_Alltoall
    (
        sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, comm
    );
}


int MPI_Alltoallv
(
    const void* sendbuf, const int sendcounts[], const int sdispls[],
    MPI_Datatype sendtype, void* recvbuf, const int recvcounts[],
    const int rdispls[], MPI_Datatype recvtype, MPI_Comm comm
)
{
    const int n = mpiCounters::size(comm);
    counts().collective
    (
        mpiCounters::Alltoallv,
        sendbuf == MPI_IN_PLACE
      ? mpiCounters::bytes(recvcounts, n, recvtype)
      : mpiCounters::bytes(sendcounts, n, sendtype)
    );
    return PMPI_Alltoallv
    (
        sendbuf, sendcounts, sdispls, sendtype, recvbuf, recvcounts,
        rdispls, recvtype, comm
    );
}


// * * * * * * * * * * * * * * * * * Finalize  * * * * * * * * * * * * * * * //

int MPI_Finalize()
{
    counts().write();
    return PMPI_Finalize();
}

} // End extern "C"


// ************************************************************************* //
