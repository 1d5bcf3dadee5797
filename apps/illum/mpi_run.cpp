#include "mpi_run.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fmt/core.h>
#include <map>
#include <unistd.h>
#include <vector>

#ifdef ILLUM_HAVE_MPI
#include <mpi.h>
#endif

namespace illum::cli {

namespace {

#ifdef ILLUM_HAVE_MPI

// Launchers announce the job in the environment: Open MPI's mpirun, PMI (MPICH's hydra, srun --mpi=pmi2)
// and PMIx (srun --mpi=pmix, Open MPI 5).
bool launched_by_mpi() {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
        if (std::getenv(v)) return true;
    return false;
}

class MpiGroup final : public RenderGroup {
public:
    MpiGroup() {
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
    int rank() const override { return rank_; }
    int size() const override { return size_; }

    void sum(std::span<double> values, bool everywhere) override {
        auto t0 = std::chrono::steady_clock::now();
        // In pieces whose count fits MPI's int.
        constexpr std::size_t kPiece = std::size_t(1) << 26;
        for (std::size_t i = 0; i < values.size(); i += kPiece) {
            int n = int(std::min(kPiece, values.size() - i));
            double* p = values.data() + i;
            if (rank_ == 0)
                MPI_Reduce(MPI_IN_PLACE, p, n, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
            else
                MPI_Reduce(p, nullptr, n, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
            // A broadcast of rank 0's sum rather than an allreduce, whose rounding may differ by rank.
            if (everywhere) MPI_Bcast(p, n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
        }
        communication_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }

    bool broadcast(bool value) override {
        auto t0 = std::chrono::steady_clock::now();
        int v = value ? 1 : 0;
        MPI_Bcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD);
        communication_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return v != 0;
    }

private:
    int rank_ = 0, size_ = 1;
};

MpiGroup* g_group = nullptr;

// A rank stopped by a catchable signal (scancel, a time limit, kill) says so and exits 2, which mpirun
// reports as the job's status, naming the rank. (SIGKILL cannot be caught: mpirun then names the rank and
// exits 128 + 9.) The message is made beforehand: a handler may only write and _exit.
char g_signal_message[160];

extern "C" void on_stop_signal(int signal) {
    char line[200];
    int n = std::snprintf(line, sizeof line, "%s%d\n", g_signal_message, signal);
    if (n > 0) {
        ssize_t written = ::write(2, line, std::size_t(std::min<int>(n, int(sizeof line) - 1)));
        (void)written; // nothing to do if stderr is gone
    }
    ::_exit(2);
}

#endif

} // namespace

MpiRun::MpiRun(int* argc, char*** argv) {
#ifdef ILLUM_HAVE_MPI
    if (!launched_by_mpi()) return;
    // Only the main thread calls MPI (between the parallel passes).
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    g_group = new MpiGroup();
    if (g_group->size() > 1) {
        std::snprintf(g_signal_message, sizeof g_signal_message,
                      "error: rank %d of %d: stopped by signal ", g_group->rank(), g_group->size());
        for (int sig : {SIGTERM, SIGINT, SIGHUP, SIGXCPU, SIGUSR1, SIGUSR2}) std::signal(sig, on_stop_signal);
    }
#else
    (void)argc;
    (void)argv;
#endif
}

MpiRun::~MpiRun() {
#ifdef ILLUM_HAVE_MPI
    if (!g_group) return;
    delete g_group;
    g_group = nullptr;
    MPI_Finalize();
#endif
}

RenderGroup* MpiRun::group() {
#ifdef ILLUM_HAVE_MPI
    return g_group;
#else
    return nullptr;
#endif
}

void MpiRun::agree(const std::string& error) {
#ifdef ILLUM_HAVE_MPI
    if (!g_group) return;
    const int rank = g_group->rank(), size = g_group->size();
    int length = int(error.size());
    std::vector<int> lengths(std::size_t(size), 0);
    MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD);
    bool failed = false;
    for (int l : lengths) failed |= l > 0;
    if (!failed) return;
    // Rank 0 gathers the messages and prints each once, with the ranks that gave it.
    std::vector<int> offsets(std::size_t(size), 0);
    int total = 0;
    for (int r = 0; r < size; ++r) offsets[std::size_t(r)] = total, total += lengths[std::size_t(r)];
    std::string all(std::size_t(rank == 0 ? total : 0), '\0');
    MPI_Gatherv(error.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
                MPI_COMM_WORLD);
    if (rank == 0) {
        std::map<std::string, std::vector<int>> by_message;
        for (int r = 0; r < size; ++r)
            if (lengths[std::size_t(r)] > 0)
                by_message[all.substr(std::size_t(offsets[std::size_t(r)]), std::size_t(lengths[std::size_t(r)]))]
                    .push_back(r);
        for (const auto& [message, ranks] : by_message) {
            std::string who;
            for (int r : ranks) {
                if (!who.empty()) who += ',';
                who += std::to_string(r);
            }
            fmt::print(stderr, "error: rank{} {} of {}: {}\n", ranks.size() > 1 ? "s" : "", who, size, message);
        }
        fmt::print(stderr, "error: the render did not start; no output was written\n");
    }
    throw ReportedFailure{};
#else
    (void)error;
#endif
}

void MpiRun::abort(int code) {
#ifdef ILLUM_HAVE_MPI
    if (g_group && g_group->size() > 1) MPI_Abort(MPI_COMM_WORLD, code);
#endif
    std::fflush(stderr);
    std::_Exit(code);
}

} // namespace illum::cli
