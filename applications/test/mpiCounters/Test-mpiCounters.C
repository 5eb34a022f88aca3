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
    flapFoamMPICountersProbe

Description
    Sends known MPI messages on exactly 2 ranks, for the test of
    libflapFoamMPICounters.so (applications/test/mpiCounters/Alltest, which
    runs it under mpirun with the library preloaded and checks the counts
    files against the table there).  Plain MPI, no OpenFOAM.  Checks what
    it receives and exits non-zero on a wrong value or a wrong number of
    ranks.

    Rank 0 sends rank 1: 3 x 1000 doubles (MPI_Send), 50 doubles to
    MPI_PROC_NULL (MPI_Send), 100 chars (MPI_Bsend), 10 ints (MPI_Isend).
    Rank 1 sends rank 0: 2 x 5 floats (MPI_Isend) and 5 floats more through
    a communicator whose ranks are reversed (its rank 1 is world rank 0:
    still one destination), 2 ints (MPI_Ssend).
    Both: MPI_Sendrecv of 7 ints with the other rank; MPI_Allreduce of 4
    doubles and, in place, of 2 ints; MPI_Alltoall of 1 int per rank;
    MPI_Alltoallv of r + j + 1 ints from rank r to rank j; MPI_Bcast of
    3 longs from rank 0; MPI_Gatherv of r + 1 doubles to rank 0;
    MPI_Barrier.

Usage
    \verbatim
    mpirun -np 2 -x LD_PRELOAD=$FLAPFOAM_LIBBIN/libflapFoamMPICounters.so \
        -x FLAPFOAM_MPI_COUNTS=DIR flapFoamMPICountersProbe
    \endverbatim

\*---------------------------------------------------------------------------*/

#include <mpi.h>
#include <cstdio>
#include <numeric>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Failed checks so far
int nFailed = 0;

void check(bool ok, const char* what)
{
    if (!ok)
    {
        std::fprintf(stderr, "flapFoamMPICountersProbe: wrong %s\n", what);
        ++nFailed;
    }
}


//- Rank 0's sends and rank 1's receives of them
void fromRank0(int rank)
{
    std::vector<double> d(1000, 1.5);
    std::vector<char> c(100, 'x');
    std::vector<int> i(10, 7);
    if (rank == 0)
    {
        for (int k = 0; k < 3; ++k)
        {
            MPI_Send(d.data(), 1000, MPI_DOUBLE, 1, k, MPI_COMM_WORLD);
        }
        MPI_Send(d.data(), 50, MPI_DOUBLE, MPI_PROC_NULL, 0, MPI_COMM_WORLD);

        std::vector<char> buf(1000 + MPI_BSEND_OVERHEAD);
        MPI_Buffer_attach(buf.data(), int(buf.size()));
        MPI_Bsend(c.data(), 100, MPI_CHAR, 1, 3, MPI_COMM_WORLD);
        void* detached = nullptr;
        int size = 0;
        MPI_Buffer_detach(&detached, &size);

        MPI_Request req;
        MPI_Isend(i.data(), 10, MPI_INT, 1, 4, MPI_COMM_WORLD, &req);
        MPI_Wait(&req, MPI_STATUS_IGNORE);
        return;
    }

    double sum = 0;
    for (int k = 0; k < 3; ++k)
    {
        d.assign(1000, 0);
        MPI_Recv(d.data(), 1000, MPI_DOUBLE, 0, k, MPI_COMM_WORLD,
            MPI_STATUS_IGNORE);
        sum += std::accumulate(d.begin(), d.end(), 0.0);
    }
    check(sum == 4500, "doubles (MPI_Send)");
    c.assign(100, 0);
    MPI_Recv(c.data(), 100, MPI_CHAR, 0, 3, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    check(c[99] == 'x', "chars (MPI_Bsend)");
    i.assign(10, 0);
    MPI_Recv(i.data(), 10, MPI_INT, 0, 4, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    check(i[9] == 7, "ints (MPI_Isend)");
}


//- Rank 1's sends (world and reversed communicator) and rank 0's receives
void fromRank1(int rank, MPI_Comm reversed)
{
    std::vector<float> f(15, 2.0f);
    std::vector<int> i(2, 3);
    if (rank == 1)
    {
        MPI_Request req[3];
        MPI_Isend(&f[0], 5, MPI_FLOAT, 0, 5, MPI_COMM_WORLD, &req[0]);
        MPI_Isend(&f[5], 5, MPI_FLOAT, 0, 6, MPI_COMM_WORLD, &req[1]);
        MPI_Isend(&f[10], 5, MPI_FLOAT, 1, 7, reversed, &req[2]);
        MPI_Ssend(i.data(), 2, MPI_INT, 0, 8, MPI_COMM_WORLD);
        MPI_Waitall(3, req, MPI_STATUSES_IGNORE);
        return;
    }

    f.assign(15, 0);
    MPI_Recv(&f[0], 5, MPI_FLOAT, 1, 5, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    MPI_Recv(&f[5], 5, MPI_FLOAT, 1, 6, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    MPI_Recv(&f[10], 5, MPI_FLOAT, 0, 7, reversed, MPI_STATUS_IGNORE);
    check
    (
        std::accumulate(f.begin(), f.end(), 0.0f) == 30,
        "floats (MPI_Isend)"
    );
    i.assign(2, 0);
    MPI_Recv(i.data(), 2, MPI_INT, 1, 8, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    check(i[1] == 3, "ints (MPI_Ssend)");
}


//- The calls both ranks make
void both(int rank)
{
    const int other = 1 - rank;
    int s[7] = {rank, rank, rank, rank, rank, rank, rank}, r[7];
    MPI_Sendrecv(s, 7, MPI_INT, other, 9, r, 7, MPI_INT, other, 9,
        MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    check(r[6] == other, "ints (MPI_Sendrecv)");

    double a[4] = {1, 2, 3, double(rank)}, b[4];
    MPI_Allreduce(a, b, 4, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    check(b[3] == 1, "sum (MPI_Allreduce)");
    int m[2] = {rank, rank};
    MPI_Allreduce(MPI_IN_PLACE, m, 2, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    check(m[0] == 1, "max (MPI_Allreduce in place)");

    int all[2] = {10*rank, 10*rank + 1}, got[2];
    MPI_Alltoall(all, 1, MPI_INT, got, 1, MPI_INT, MPI_COMM_WORLD);
    check(got[other] == 10*other + rank, "int (MPI_Alltoall)");

    // r + j + 1 ints from rank r to rank j
    const int sendCounts[2] = {rank + 1, rank + 2};
    const int sendDispls[2] = {0, rank + 1};
    const int recvCounts[2] = {rank + 1, rank + 2};
    const int recvDispls[2] = {0, rank + 1};
    std::vector<int> v(2*rank + 3, rank), w(2*rank + 3, -1);
    MPI_Alltoallv(v.data(), sendCounts, sendDispls, MPI_INT, w.data(),
        recvCounts, recvDispls, MPI_INT, MPI_COMM_WORLD);
    check(w[recvDispls[other]] == other, "ints (MPI_Alltoallv)");

    long l[3] = {rank ? 0 : 42L, 0, 0};
    MPI_Bcast(l, 3, MPI_LONG, 0, MPI_COMM_WORLD);
    check(l[0] == 42, "long (MPI_Bcast)");

    double g[2] = {double(rank), double(rank)}, gathered[3];
    const int gatherCounts[2] = {1, 2}, gatherDispls[2] = {0, 1};
    MPI_Gatherv(g, rank + 1, MPI_DOUBLE, gathered, gatherCounts,
        gatherDispls, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    check(rank == 1 || gathered[2] == 1, "doubles (MPI_Gatherv)");

    MPI_Barrier(MPI_COMM_WORLD);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char* argv[])
{
    MPI_Init(&argc, &argv);
    int rank = 0, nRanks = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nRanks);
    if (nRanks != 2)
    {
        std::fprintf(stderr, "flapFoamMPICountersProbe: runs on 2 ranks,"
            " not %d\n", nRanks);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }

    MPI_Comm reversed;
    MPI_Comm_split(MPI_COMM_WORLD, 0, -rank, &reversed);

    fromRank0(rank);
    fromRank1(rank, reversed);
    both(rank);

    MPI_Comm_free(&reversed);
    MPI_Finalize();
    return nFailed ? 1 : 0;
}


// ************************************************************************* //
