// Progress on stderr (DESIGN.md §3): a bar with percentage, rate and ETA when stderr is a terminal,
// a plain line every few seconds otherwise; nothing when quiet. Thread-safe: work is reported by
// adding to an atomic counter, and one thread at a time prints.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace illum {

class Progress {
public:
    // total: units of work (0 when unknown, as for a time budget); unit: what one unit is ("samples").
    Progress(std::string label, std::uint64_t total, std::string unit, bool quiet);
    ~Progress();
    void add(std::uint64_t done);
    void set_total(std::uint64_t total) { total_ = total; }
    // Fraction from the caller (for time-budgeted work), used instead of done/total when >= 0.
    void set_fraction(double f) { fraction_ = f; }
    void finish();
    double elapsed_seconds() const;

private:
    void print(bool final);
    std::string label_, unit_;
    std::atomic<std::uint64_t> total_;
    std::atomic<std::uint64_t> done_{0};
    std::atomic<double> fraction_{-1};
    bool quiet_, tty_, finished_ = false;
    std::chrono::steady_clock::time_point start_;
    std::atomic<std::int64_t> last_print_ns_{0}; // since start_; read by every worker, so atomic
    std::mutex mutex_;
};

} // namespace illum
