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

Program
    pingPong (bench/scaling)

Description
    The cost of one message and of one byte between two MPI ranks on this
    machine, for the scaling model (bench/scaling/run compiles it with
    mpicc and runs it under mpirun -np 2): rank 0 sends N bytes to rank 1,
    which sends them back, R round trips per size; a message of N bytes
    costs alpha + N beta one way.  Prints, for each size, the median
    one-way time over 5 batches:

        pingPong: bytes N seconds T

    and then the fit from the smallest (8 B) and the largest (4 MiB) size:

        pingPong: alpha A beta B

    Standard MPI and C only.

\*---------------------------------------------------------------------------*/

#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

#define N_SIZES 4
#define N_BATCHES 5

static int compare(const void* a, const void* b)
{
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

/* One-way seconds of a message of n bytes: median over the batches of
   the mean over r round trips, halved */
static double oneWay(char* buf, int n, int r, int rank)
{
    double t[N_BATCHES];
    for (int b = 0; b < N_BATCHES; ++b)
    {
        MPI_Barrier(MPI_COMM_WORLD);
        const double start = MPI_Wtime();
        for (int i = 0; i < r; ++i)
        {
            if (rank == 0)
            {
                MPI_Send(buf, n, MPI_CHAR, 1, 0, MPI_COMM_WORLD);
                MPI_Recv(buf, n, MPI_CHAR, 1, 0, MPI_COMM_WORLD,
                         MPI_STATUS_IGNORE);
            }
            else
            {
                MPI_Recv(buf, n, MPI_CHAR, 0, 0, MPI_COMM_WORLD,
                         MPI_STATUS_IGNORE);
                MPI_Send(buf, n, MPI_CHAR, 0, 0, MPI_COMM_WORLD);
            }
        }
        t[b] = (MPI_Wtime() - start)/(2.0*r);
    }
    qsort(t, N_BATCHES, sizeof(double), compare);
    return t[N_BATCHES/2];
}

int main(int argc, char* argv[])
{
    const int sizes[N_SIZES] = {8, 4096, 262144, 4194304};
    const int trips[N_SIZES] = {2000, 1000, 100, 20};
    double seconds[N_SIZES];
    int rank, nRanks;

    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nRanks);
    if (nRanks != 2)
    {
        if (rank == 0)
        {
            fprintf(stderr, "pingPong: needs 2 ranks, got %d\n", nRanks);
        }
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    char* buf = calloc(sizes[N_SIZES - 1], 1);
    for (int s = 0; s < N_SIZES; ++s)
    {
        seconds[s] = oneWay(buf, sizes[s], trips[s], rank);
        if (rank == 0)
        {
            printf("pingPong: bytes %d seconds %.6e\n", sizes[s], seconds[s]);
        }
    }
    if (rank == 0)
    {
        const double beta = (seconds[N_SIZES - 1] - seconds[0])
            /(sizes[N_SIZES - 1] - sizes[0]);
        printf("pingPong: alpha %.6e beta %.6e\n",
               seconds[0] - sizes[0]*beta, beta);
    }
    free(buf);
    MPI_Finalize();
    return 0;
}
