#include "glintlab/gl/gpu_timer.h"

#include <algorithm>
#include <cmath>

#include <epoxy/gl.h>

namespace glintlab::gl {

PassTimer::PassTimer() {
    glCreateQueries(GL_TIME_ELAPSED, 1, &query_);
}

PassTimer::~PassTimer() {
    glDeleteQueries(1, &query_);
}

void PassTimer::begin() {
    glBeginQuery(GL_TIME_ELAPSED, query_);
}

void PassTimer::end() {
    glEndQuery(GL_TIME_ELAPSED);
    pending_ = true;
}

double PassTimer::elapsed_ms() {
    if (pending_) {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(query_, GL_QUERY_RESULT, &ns);  // waits for the GPU
        last_ms_ = static_cast<double>(ns) * 1e-6;
        pending_ = false;
    }
    return last_ms_;
}

TimingStats timing_stats(std::vector<double> samples) {
    TimingStats s;
    if (samples.empty()) return s;
    std::sort(samples.begin(), samples.end());
    auto rank = [&](double q) {
        // Nearest rank: the smallest sample with at least q of the samples at or below it.
        const size_t n = samples.size();
        const size_t k = static_cast<size_t>(std::ceil(q * static_cast<double>(n)));
        return samples[std::clamp<size_t>(k, 1, n) - 1];
    };
    s.frames = static_cast<int>(samples.size());
    s.median_ms = rank(0.5);
    s.p10_ms = rank(0.1);
    s.p90_ms = rank(0.9);
    s.min_ms = samples.front();
    s.max_ms = samples.back();
    return s;
}

}  // namespace glintlab::gl
