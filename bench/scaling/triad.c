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
    triad (bench/scaling)

Description
    The memory bandwidth of this machine's socket, for the scaling bench's
    bound on a PIMPLE step (a step of sparse solves streams its matrices
    and vectors): every MPI rank runs the STREAM triad a[i] = b[i] + s c[i]
    on arrays of its own (first touched by it), all ranks together between
    barriers, R repetitions.  Bytes counted as STREAM counts them, 24 per
    element (b and c read, a written; the write-allocate read of a is not
    counted).  Prints the bandwidth of all ranks together, the sum of
    their bytes over the slowest rank's time, the best and the median of
    the repetitions:

        triad: ranks P elements N MB/rank M best B GB/s median D GB/s
        triad: per rank best B/P GB/s

    Run at 1 rank and at one rank per core (bench/scaling/run, the
    archive's runTimed): the ratio is how far the socket's bandwidth is
    shared.  Optional argument: elements per array (default 2^25: 805 MB
    a rank, far past any cache).  Standard MPI and C only.

\*---------------------------------------------------------------------------*/

#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

#define N_REPEAT 10

static int compare(const void* a, const void* b)
{
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

/* Seconds of each repetition: the slowest rank's (a reduction of max) */
static void timeTriad(double* a, double* b, double* c, long n, double* t)
{
    const double s = 3.0;
    for (int r = 0; r < N_REPEAT; ++r)
    {
        MPI_Barrier(MPI_COMM_WORLD);
        const double start = MPI_Wtime();
        for (long i = 0; i < n; ++i)
        {
            a[i] = b[i] + s*c[i];
        }
        const double mine = MPI_Wtime() - start;
        MPI_Allreduce(&mine, &t[r], 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    }
}

int main(int argc, char* argv[])
{
    int rank, nRanks;
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nRanks);

    const long n = argc > 1 ? atol(argv[1]) : (1L << 25);
    double* a = n > 0 ? malloc(n*sizeof(double)) : NULL;
    double* b = n > 0 ? malloc(n*sizeof(double)) : NULL;
    double* c = n > 0 ? malloc(n*sizeof(double)) : NULL;
    if (!a || !b || !c)
    {
        fprintf(stderr, "triad: elements '%s': not allowed or no memory"
                " (a positive integer)\n", argc > 1 ? argv[1] : "");
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    for (long i = 0; i < n; ++i)
    {
        a[i] = 0.0; b[i] = 1.0; c[i] = 2.0;
    }
    double t[N_REPEAT];
    timeTriad(a, b, c, n, t);
    qsort(t, N_REPEAT, sizeof(double), compare);
    if (rank == 0)
    {
        const double bytes = 24.0*n*nRanks;
        printf("triad: ranks %d elements %ld MB/rank %.0f best %.2f GB/s"
               " median %.2f GB/s\n", nRanks, n, 24.0*n/1e6,
               bytes/t[0]/1e9, bytes/t[N_REPEAT/2]/1e9);
        printf("triad: per rank best %.2f GB/s\n", bytes/t[0]/1e9/nRanks);
    }
    int ok = a[n - 1] == 7.0;
    MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
    free(a); free(b); free(c);
    MPI_Finalize();
    if (!ok && rank == 0)
    {
        fprintf(stderr, "triad: wrong result\n");
    }
    return ok ? 0 : 1;
}
