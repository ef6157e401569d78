// exidel CLI (internal): progress on standard error for runs longer than about a second.
//
// Only when standard error is a terminal (a log file or a pipe gets nothing): one line,
// "exidel: triangulating... 2.5 s", rewritten in place twice a second from the first
// second on, and erased when the run ends, so that the run's own messages and --stats
// are all that remains. Phases are named by the command as it goes.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

namespace exidel::cli {

class Progress {
public:
    /// Shows progress iff `enabled` and standard error is a terminal.
    explicit Progress(bool enabled = true);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// The step the run is in now ("reading 'points.xy'", "triangulating", ...).
    void phase(std::string_view name);
    /// Erases the line and stops (before printing anything else on standard error).
    void stop();

private:
    void run();

    using Clock = std::chrono::steady_clock;
    Clock::time_point start_ = Clock::now();
    std::mutex mutex_;
    std::condition_variable wake_;
    std::string phase_;
    bool stopping_ = false;
    bool shown_ = false;
    std::thread thread_;
};

}  // namespace exidel::cli
