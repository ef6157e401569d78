// exidel: the one parallel loop of the project (the strips of the triangulation, the
// chunks of the research studies).
//
// Jobs are handed out one at a time from a shared counter, so which thread runs which
// job varies from run to run: callers make each job write only its own slot, and the
// result never depends on the thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace exidel {

/// Runs job(0) ... job(count - 1) on min(threads, count) threads, the caller's included
/// (threads 0 counts as 1). When a job throws, no new job starts, every thread is joined,
/// and the exception of the lowest-numbered thread that threw is rethrown.
template <class Job>
void parallel_for(std::size_t count, unsigned threads, Job&& job) {
    const std::size_t workers = std::min<std::size_t>(std::max(threads, 1u), count);
    if (workers <= 1) {
        for (std::size_t j = 0; j < count; ++j) job(j);
        return;
    }
    std::atomic<std::size_t> next{0};
    std::vector<std::exception_ptr> errors(workers);
    auto work = [&](std::size_t w) {
        try {
            for (std::size_t j; (j = next.fetch_add(1)) < count;) job(j);
        } catch (...) {
            errors[w] = std::current_exception();
            next = count;  // stop handing out jobs
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    for (std::size_t w = 1; w < workers; ++w) {
        // A thread that cannot be created (too little memory for its stack under a
        // ulimit -v, a process limit) leaves its jobs to the threads that could: the
        // result does not depend on the thread count. Letting the exception escape
        // would destroy joinable threads, which terminates the program.
        try {
            pool.emplace_back(work, w);
        } catch (const std::system_error&) {
            break;
        }
    }
    work(0);
    for (auto& t : pool) t.join();
    for (auto& e : errors) {
        if (e) std::rethrow_exception(e);
    }
}

}  // namespace exidel
