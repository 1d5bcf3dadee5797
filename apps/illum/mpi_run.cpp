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
#include "../plugins/mpi_shim.h"
#include "load_module.h"
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

// The MPI module's calls (illum-mpi.so, loaded when a launcher started the process).
const IllumMpiShim* g_mpi = nullptr;

class MpiGroup final : public RenderGroup {
public:
    MpiGroup(int rank, int size) : rank_(rank), size_(size) {}
    int rank() const override { return rank_; }
    int size() const override { return size_; }

    void sum(std::span<double> values, bool everywhere) override {
        auto t0 = std::chrono::steady_clock::now();
        // In pieces whose count fits MPI's int.
        constexpr std::size_t kPiece = std::size_t(1) << 26;
        for (std::size_t i = 0; i < values.size(); i += kPiece)
            g_mpi->sum_doubles(values.data() + i, int(std::min(kPiece, values.size() - i)),
                               everywhere ? 1 : 0);
        communication_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }

    bool broadcast(bool value) override {
        auto t0 = std::chrono::steady_clock::now();
        int v = g_mpi->broadcast_int(value ? 1 : 0);
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
    std::string error;
    auto entry = reinterpret_cast<const IllumMpiShim* (*)()>(
        plugin::module_symbol("illum-mpi.so", "illum_mpi_shim", plugin::ModuleScope::Global, &error));
    const IllumMpiShim* shim = entry ? entry() : nullptr;
    if (shim && shim->version != kIllumMpiShimVersion) {
        error = "illum-mpi.so is from another build (interface " + std::to_string(shim->version) + ", not " +
                std::to_string(kIllumMpiShimVersion) + ")";
        shim = nullptr;
    }
    if (!shim) {
        // Before main's handlers exist: said here, with the exit code of every other failure.
        fmt::print(stderr, "error: an MPI launcher started illum, but its MPI module did not load: {}\n",
                   error);
        std::exit(2);
    }
    g_mpi = shim;
    int rank = 0, size = 1;
    g_mpi->init(argc, argv, &rank, &size);
    g_group = new MpiGroup(rank, size);
    if (g_group->size() > 1) {
        std::snprintf(g_signal_message, sizeof g_signal_message, "error: rank %d of %d: stopped by signal ",
                      g_group->rank(), g_group->size());
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
    g_mpi->finalize();
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
    g_mpi->allgather_int(length, lengths.data());
    bool failed = false;
    for (int l : lengths) failed |= l > 0;
    if (!failed) return;
    // Rank 0 gathers the messages and prints each once, with the ranks that gave it.
    std::vector<int> offsets(std::size_t(size), 0);
    int total = 0;
    for (int r = 0; r < size; ++r) offsets[std::size_t(r)] = total, total += lengths[std::size_t(r)];
    std::string all(std::size_t(rank == 0 ? total : 0), '\0');
    g_mpi->gather_chars(error.data(), length, all.data(), lengths.data(), offsets.data());
    if (rank == 0) {
        std::map<std::string, std::vector<int>> by_message;
        for (int r = 0; r < size; ++r)
            if (lengths[std::size_t(r)] > 0)
                by_message[all.substr(std::size_t(offsets[std::size_t(r)]),
                                      std::size_t(lengths[std::size_t(r)]))]
                    .push_back(r);
        for (const auto& [message, ranks] : by_message) {
            std::string who;
            for (int r : ranks) {
                if (!who.empty()) who += ',';
                who += std::to_string(r);
            }
            fmt::print(stderr, "error: rank{} {} of {}: {}\n", ranks.size() > 1 ? "s" : "", who, size,
                       message);
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
    if (g_group && g_group->size() > 1) g_mpi->abort(code);
#endif
    std::fflush(stderr);
    std::_Exit(code);
}

} // namespace illum::cli
