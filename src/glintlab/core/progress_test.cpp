#include "glintlab/core/progress.h"

#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <poll.h>
#include <pty.h>
#include <unistd.h>

namespace glintlab {
namespace {

TEST(Progress, FormatsDurations) {
    EXPECT_EQ(format_duration(0.0), "0.0s");
    EXPECT_EQ(format_duration(3.14), "3.1s");
    EXPECT_EQ(format_duration(59.9), "59.9s");
    EXPECT_EQ(format_duration(125.0), "2m05s");
    EXPECT_EQ(format_duration(3725.0), "1h02m");
    EXPECT_EQ(format_duration(-1.0), "?");
}

TEST(Progress, FormatsLineWithBarPercentAndEstimate) {
    // 42 of 100 after 3.0 s: rate 14/s, 58 left -> 58/14 = 4.14 s.
    EXPECT_EQ(format_progress_line("render", 42, 100, 3.0, 10),
              "render [####......] 42% 3.0s elapsed, 4.1s left");
    EXPECT_EQ(format_progress_line("t", 0, 50, 0.0, 4), "t [....] 0% 0.0s elapsed, ? left");
    // Floors: 99.9% is not shown as done.
    EXPECT_EQ(format_progress_line("t", 999, 1000, 10.0, 4),
              "t [###.] 99% 10.0s elapsed, 0.0s left");
    EXPECT_EQ(format_progress_line("t", 1000, 1000, 61.0, 4), "t [####] 100% 1m01s elapsed");
    // Overshooting work saturates instead of drawing past the bar.
    EXPECT_EQ(format_progress_line("t", 1500, 1000, 1.0, 4), "t [####] 100% 1.0s elapsed");
}

TEST(Progress, CountsConcurrentUpdatesExactly) {
    ProgressReporter progress(8 * 10000, "work", /*quiet=*/true);
    std::vector<std::thread> threads;
    for (int t = 0; t < 8; ++t)
        threads.emplace_back([&] {
            for (int i = 0; i < 10000; ++i) progress.update();
        });
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(progress.work_done(), 80000);
    progress.done();
    const double at_done = progress.elapsed_seconds();
    EXPECT_GE(at_done, 0.0);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_EQ(progress.elapsed_seconds(), at_done);  // frozen at done()
}

TEST(Progress, SilentWhenQuietOrNotATerminal) {
    // gtest's capture redirects stderr to a file, so isatty is false there.
    for (bool quiet : {true, false}) {
        ::testing::internal::CaptureStderr();
        {
            ProgressReporter progress(10, "job", quiet);
            EXPECT_FALSE(progress.draws());
            for (int i = 0; i < 10; ++i) progress.update();
            progress.done();
        }
        EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << quiet;
    }
}

// On a terminal (a pseudo-terminal standing in for stderr) the bar is drawn once at
// start and once at done(); 1000 updates within far less than the 100 ms redraw interval
// add at most one redraw (if the loop happens to straddle a 100 ms boundary).
TEST(Progress, DrawsOnTerminalThrottledWithFinalLine) {
    int master = -1, slave = -1;
    if (openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) GTEST_SKIP() << "no pty";
    const int saved = dup(STDERR_FILENO);
    dup2(slave, STDERR_FILENO);
    {
        ProgressReporter progress(1000, "job", /*quiet=*/false);
        EXPECT_TRUE(progress.draws());
        for (int i = 0; i < 1000; ++i) progress.update();
        progress.done();
        progress.done();  // second call draws nothing
    }
    std::fflush(stderr);
    dup2(saved, STDERR_FILENO);
    close(saved);
    close(slave);
    std::string out;
    char buf[4096];
    pollfd pfd{master, POLLIN, 0};
    while (poll(&pfd, 1, 100) > 0) {
        const ssize_t n = read(master, buf, sizeof(buf));
        if (n <= 0) break;
        out.append(buf, size_t(n));
    }
    close(master);
    size_t lines = 0;
    for (size_t at = out.find("job ["); at != std::string::npos; at = out.find("job [", at + 1))
        ++lines;
    EXPECT_GE(lines, 2u) << out;
    EXPECT_LE(lines, 3u) << out;
    EXPECT_NE(out.find("job [..."), std::string::npos) << out;  // the initial, empty bar
    EXPECT_NE(out.find("] 100% "), std::string::npos) << out;
    EXPECT_EQ(out.find("left", out.find("] 100% ")), std::string::npos) << out;
    EXPECT_EQ(out.back(), '\n') << out;  // the final line ends the line
}

}  // namespace
}  // namespace glintlab
