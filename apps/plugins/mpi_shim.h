// The MPI calls illum makes, behind a table of C functions that the module illum-mpi.so provides
// (mpi_shim.cpp). The program loads the module only when an MPI launcher started it (apps/illum/mpi_run.cpp),
// so an ordinary run does not load Open MPI's or MPICH's libraries at all: they cost about a millisecond of
// start-up (docs/performance.md, "Start-up without MPI and the HTTP server").
#pragma once

extern "C" {

struct IllumMpiShim {
    int version; // kIllumMpiShimVersion of the module's build
    // MPI_Init_thread with MPI_THREAD_FUNNELED; the job's rank and size.
    void (*init)(int* argc, char*** argv, int* rank, int* size);
    void (*finalize)();
    // MPI_Reduce of n doubles to rank 0 (in place there), then, with `everywhere`, MPI_Bcast of the sum.
    void (*sum_doubles)(double* values, int n, int everywhere);
    // Rank 0's value, on every rank (MPI_Bcast of one int).
    int (*broadcast_int)(int value);
    // Every rank's value, in rank order (MPI_Allgather of one int).
    void (*allgather_int)(int value, int* all);
    // Rank 0 receives every rank's bytes at offsets[r] (MPI_Gatherv of chars).
    void (*gather_chars)(const char* bytes, int length, char* all, const int* lengths, const int* offsets);
    void (*abort)(int code);
};

// The module's one entry point (dlsym name "illum_mpi_shim").
const IllumMpiShim* illum_mpi_shim();
}

constexpr int kIllumMpiShimVersion = 1;
