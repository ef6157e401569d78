#include "progress.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <system_error>

namespace exidel::cli {

Progress::Progress(bool enabled) {
    if (!enabled || !::isatty(STDERR_FILENO)) return;
    // No thread (too little memory for its stack): no progress line, the run goes on.
    try {
        thread_ = std::thread([this] { run(); });
    } catch (const std::system_error&) {}
}

Progress::~Progress() { stop(); }

void Progress::phase(std::string_view name) {
    const std::lock_guard lock(mutex_);
    phase_ = name;
}

void Progress::stop() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void Progress::run() {
    // Interrupts are handled by the main thread (it removes pending output files).
    sigset_t block;
    sigemptyset(&block);
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&block, sig);
    ::pthread_sigmask(SIG_BLOCK, &block, nullptr);

    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(500), [this] { return stopping_; })) {
        const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
        if (seconds < 1) continue;
        // "\r" and erase-to-end-of-line: the line is rewritten in place.
        std::fprintf(stderr, "\r\033[Kexidel: %s... %.1f s", phase_.c_str(), seconds);
        std::fflush(stderr);
        shown_ = true;
    }
    if (shown_) {
        std::fputs("\r\033[K", stderr);
        std::fflush(stderr);
    }
}

}  // namespace exidel::cli
