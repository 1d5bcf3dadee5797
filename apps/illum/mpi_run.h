// The MPI job this process belongs to (docs/distributed.md). main() makes one MpiRun: when a launcher
// (mpirun / mpiexec of Open MPI or MPICH, Slurm's srun with PMI or PMIx) started the process and illum was
// built with MPI, it initialises MPI and the render loops get a RenderGroup of the job's ranks; otherwise
// nothing happens and illum is the ordinary single-process program.
#pragma once

#include <string>

#include "illum/render/render_group.h"

namespace illum::cli {

class MpiRun {
public:
    MpiRun(int* argc, char*** argv);
    ~MpiRun();
    MpiRun(const MpiRun&) = delete;
    MpiRun& operator=(const MpiRun&) = delete;

    // The job's ranks, or null when this process is not part of an MPI job.
    static RenderGroup* group();
    static int rank() { return group() ? group()->rank() : 0; }
    static int size() { return group() ? group()->size() : 1; }

    // Every rank calls it after a phase that may fail on some ranks only (reading the scene on each node):
    // returns when no rank failed; otherwise rank 0 prints each failing rank's message and every rank
    // throws ReportedFailure. `error` is empty on success.
    static void agree(const std::string& error);
    // Ends the whole job with `code` from any rank at any time (a failure while others may be waiting).
    [[noreturn]] static void abort(int code);
};

// An error every rank has already been told about: main() exits 2 without printing it again.
struct ReportedFailure {};

} // namespace illum::cli
