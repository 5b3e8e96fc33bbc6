#include "glintlab/core/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace glintlab {

std::string format_duration(double seconds) {
    if (!(seconds >= 0.0) || !std::isfinite(seconds)) return "?";
    if (seconds < 59.95) return fmt::format("{:.1f}s", seconds);
    const int64_t s = int64_t(std::lround(seconds));
    if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
    return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
}

std::string format_progress_line(const std::string& title, int64_t done, int64_t total,
                                 double elapsed_seconds, int bar_width) {
    const double fraction =
        total > 0 ? std::clamp(double(done) / double(total), 0.0, 1.0) : (done > 0 ? 1.0 : 0.0);
    const int filled = int(fraction * bar_width);  // floor: a full bar only when finished
    const int percent = int(fraction * 100.0);     // floor: never shows 100% before the end
    std::string line = title + " [" + std::string(size_t(filled), '#') +
                       std::string(size_t(std::max(0, bar_width - filled)), '.') + "] " +
                       std::to_string(percent) + "% " + format_duration(elapsed_seconds) +
                       " elapsed";
    if (fraction < 1.0) {
        const double left = done > 0 ? elapsed_seconds * double(total - done) / double(done) : -1.0;
        line += ", " + format_duration(left) + " left";
    }
    return line;
}

namespace {

int terminal_columns() {
    winsize ws{};
    if (ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) return ws.ws_col;
    return 80;
}

}  // namespace

ProgressReporter::ProgressReporter(int64_t total_work, std::string title, bool quiet)
    : total_(total_work),
      title_(std::move(title)),
      draws_(!quiet && isatty(STDERR_FILENO)),
      start_(Clock::now()) {
    if (draws_) draw(false);
}

ProgressReporter::~ProgressReporter() {
    done();
}

int64_t ProgressReporter::now_ns() const {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start_).count();
}

void ProgressReporter::update(int64_t work) {
    done_.fetch_add(work, std::memory_order_relaxed);
    if (!draws_) return;
    constexpr int64_t kRedrawIntervalNs = 100'000'000;  // ~10 redraws per second
    const int64_t now = now_ns();
    int64_t last = last_draw_ns_.load(std::memory_order_relaxed);
    if (now - last < kRedrawIntervalNs) return;
    // Only the thread that wins this exchange draws; the others go back to work.
    if (!last_draw_ns_.compare_exchange_strong(last, now)) return;
    draw(false);
}

void ProgressReporter::done() {
    int64_t running = -1;
    if (!finished_ns_.compare_exchange_strong(running, now_ns())) return;  // already done
    if (draws_) draw(true);
}

double ProgressReporter::elapsed_seconds() const {
    const int64_t finished = finished_ns_.load();
    return double(finished >= 0 ? finished : now_ns()) * 1e-9;
}

void ProgressReporter::draw(bool final_line) {
    std::lock_guard<std::mutex> lock(draw_mutex_);
    if (!final_line && finished_ns_.load() >= 0) return;  // a late update must not redraw
    const int64_t done = done_.load();                    // an early done() shows where it stopped
    // Room for the bar: the terminal width less the title and "[] 100% 59.9s elapsed, 59.9s left".
    const int columns = terminal_columns();
    const int bar = std::clamp(columns - int(title_.size()) - 40, 10, 50);
    const std::string line = format_progress_line(title_, done, total_, elapsed_seconds(), bar);
    // \r returns to the line start, ESC[K clears what a longer previous line left behind.
    std::fprintf(stderr, "\r%s\x1b[K%s", line.c_str(), final_line ? "\n" : "");
    std::fflush(stderr);
}

}  // namespace glintlab
