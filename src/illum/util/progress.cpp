#include "illum/util/progress.h"

#include <cstdio>
#include <fmt/format.h>
#include <unistd.h>

namespace illum {

namespace {
std::string format_duration(double s) {
    if (!(s >= 0) || s > 1e7) return "--";
    int t = int(s + 0.5);
    if (t >= 3600) return fmt::format("{}h{:02}m", t / 3600, (t / 60) % 60);
    if (t >= 60) return fmt::format("{}m{:02}s", t / 60, t % 60);
    return fmt::format("{}s", t);
}
std::string format_rate(double r) {
    if (r >= 1e9) return fmt::format("{:.2f}G", r / 1e9);
    if (r >= 1e6) return fmt::format("{:.2f}M", r / 1e6);
    if (r >= 1e3) return fmt::format("{:.1f}k", r / 1e3);
    return fmt::format("{:.0f}", r);
}
} // namespace

Progress::Progress(std::string label, std::uint64_t total, std::string unit, bool quiet)
    : label_(std::move(label)), unit_(std::move(unit)), total_(total), quiet_(quiet),
      tty_(isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

double Progress::elapsed_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::add(std::uint64_t done) {
    done_ += done;
    if (quiet_) return;
    std::int64_t now =
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start_)
            .count();
    std::int64_t interval = tty_ ? 100'000'000 : 5'000'000'000;
    if (now - last_print_ns_.load(std::memory_order_relaxed) < interval) return;
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;
    last_print_ns_.store(now, std::memory_order_relaxed);
    print(false);
}

void Progress::finish() {
    if (finished_) return;
    finished_ = true;
    if (quiet_) return;
    std::lock_guard lock(mutex_);
    print(true);
}

void Progress::print(bool final) {
    double t = elapsed_seconds();
    std::uint64_t done = done_, total = total_;
    double frac = fraction_ >= 0 ? double(fraction_) : (total ? double(done) / total : 0.0);
    if (final) frac = 1;
    frac = std::min(1.0, std::max(0.0, frac));
    double rate = t > 0 ? done / t : 0;
    double eta = frac > 0 ? t * (1 - frac) / frac : -1;
    std::string stats = fmt::format("{:5.1f}% {} {}/s, {} elapsed, ETA {}", 100 * frac, format_rate(rate),
                                    unit_, format_duration(t), final ? "0s" : format_duration(eta));
    if (tty_) {
        constexpr int width = 30;
        int filled = int(frac * width);
        std::string bar(filled, '=');
        if (filled < width) bar += '>' + std::string(width - filled - 1, ' ');
        fmt::print(stderr, "\r{} [{}] {}\x1b[K{}", label_, bar, stats, final ? "\n" : "");
    } else {
        fmt::print(stderr, "{}: {}\n", label_, stats);
    }
    std::fflush(stderr);
}

} // namespace illum
