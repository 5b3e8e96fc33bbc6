// GPU pass timing with GL_TIME_ELAPSED timer queries, and the statistics the
// benchmarks report (median and percentiles over many frames after warm-up).
#pragma once

#include <string>
#include <vector>

namespace glintlab::gl {

// One timer query per pass; begin()/end() bracket the pass's commands,
// elapsed_ms() waits for the result. Not nestable (GL allows one active
// GL_TIME_ELAPSED query at a time).
class PassTimer {
  public:
    PassTimer();
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;
    void begin();
    void end();
    // Milliseconds of the last begin/end pair (blocks until available); 0 before any.
    double elapsed_ms();

  private:
    unsigned query_ = 0;
    bool pending_ = false;
    double last_ms_ = 0.0;
};

struct TimingStats {
    int frames = 0;
    double median_ms = 0.0, p10_ms = 0.0, p90_ms = 0.0, min_ms = 0.0, max_ms = 0.0;
};

// Nearest-rank percentiles of `samples` (empty: all zero).
TimingStats timing_stats(std::vector<double> samples);

}  // namespace glintlab::gl
