// illum-mpi.so: the MPI calls of mpi_shim.h, made through MPI's C API.
#include "mpi_shim.h"

#include <mpi.h>

namespace {

int g_rank = 0;

void init(int* argc, char*** argv, int* rank, int* size) {
    // Only the main thread calls MPI (between the parallel passes).
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, rank);
    MPI_Comm_size(MPI_COMM_WORLD, size);
    g_rank = *rank;
}

void finalize() { MPI_Finalize(); }

void sum_doubles(double* values, int n, int everywhere) {
    if (g_rank == 0)
        MPI_Reduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    else
        MPI_Reduce(values, nullptr, n, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    // A broadcast of rank 0's sum rather than an allreduce, whose rounding may differ by rank.
    if (everywhere) MPI_Bcast(values, n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

int broadcast_int(int value) {
    MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return value;
}

void allgather_int(int value, int* all) {
    MPI_Allgather(&value, 1, MPI_INT, all, 1, MPI_INT, MPI_COMM_WORLD);
}

void gather_chars(const char* bytes, int length, char* all, const int* lengths, const int* offsets) {
    MPI_Gatherv(bytes, length, MPI_CHAR, all, lengths, offsets, MPI_CHAR, 0, MPI_COMM_WORLD);
}

void abort_job(int code) { MPI_Abort(MPI_COMM_WORLD, code); }

const IllumMpiShim kShim{kIllumMpiShimVersion, init,          finalize,     sum_doubles,
                         broadcast_int,        allgather_int, gather_chars, abort_job};

} // namespace

extern "C" __attribute__((visibility("default"))) const IllumMpiShim* illum_mpi_shim() { return &kShim; }
