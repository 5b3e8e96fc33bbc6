// Text progress bar on stderr for long renders and precomputations.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace glintlab {

// "3.1s", "2m05s", "1h02m": short enough for a progress line.
std::string format_duration(double seconds);

// One progress line without terminal control codes, e.g.
//   "render [#######.....] 42% 3.1s elapsed, 4.2s left"
// bar_width is the number of cells between the brackets. The remaining time
// is extrapolated linearly from the rate so far ("?" before any work is
// done); when done >= total only the elapsed time is shown.
std::string format_progress_line(const std::string& title, int64_t done, int64_t total,
                                 double elapsed_seconds, int bar_width);

// Thread-safe: update() may be called from any number of threads. Draws only
// when !quiet and stderr is a terminal; the line is redrawn in place (\r) by
// whichever thread's update() finds the last redraw at least 100 ms old, so
// no extra thread is needed and contention costs one atomic load.
class ProgressReporter {
  public:
    ProgressReporter(int64_t total_work, std::string title, bool quiet);
    ~ProgressReporter();  // calls done() if it was not called
    ProgressReporter(const ProgressReporter&) = delete;
    ProgressReporter& operator=(const ProgressReporter&) = delete;

    void update(int64_t work = 1);
    void done();  // final line with the total elapsed time; later calls do nothing
    double elapsed_seconds() const;  // stops advancing at done()
    int64_t work_done() const { return done_.load(std::memory_order_relaxed); }
    bool draws() const { return draws_; }

  private:
    using Clock = std::chrono::steady_clock;
    int64_t now_ns() const;
    void draw(bool final_line);

    const int64_t total_;
    const std::string title_;
    const bool draws_;
    const Clock::time_point start_;
    std::atomic<int64_t> done_{0};
    std::atomic<int64_t> last_draw_ns_{0};
    std::atomic<int64_t> finished_ns_{-1};  // elapsed at done(), -1 while running
    std::mutex draw_mutex_;
};

}  // namespace glintlab
