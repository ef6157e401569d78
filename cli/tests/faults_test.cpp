// Faults a user meets, end to end on the built binary: a full disk, a file size limit, too
// little memory, an output directory removed during the run. Each must be a clear error
// on standard error, exit status 1, and leave no output and no temporary file behind
// (docs/cli.md, "Faults").
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "run_binary.hpp"

namespace {

namespace fs = std::filesystem;
using namespace exidel::cli_test;

// Under AddressSanitizer or ThreadSanitizer the process reserves terabytes of address
// space for its shadow memory, so an address-space limit (ulimit -v) stops it before main().
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool shadow_memory = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool shadow_memory = true;
#else
constexpr bool shadow_memory = false;
#endif
#else
constexpr bool shadow_memory = false;
#endif

/// A fresh, empty directory of the test work directory.
std::string fresh_dir(const std::string& name) {
    const std::string dir = work_path(name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// n uniform points in the unit square as an f64 file (x, y little-endian doubles).
std::string f64_points(const std::string& path, std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> xy(2 * n);
    for (double& v : xy) v = u(rng);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(xy.data()),
               static_cast<std::streamsize>(xy.size() * sizeof(double)));
    return path;
}

/// The names of the files in `dir`.
std::vector<std::string> files_in(const std::string& dir) {
    std::vector<std::string> names;
    if (!fs::exists(dir)) return names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename());
    return names;
}

/// Runs `sh -c "<limits>; exec exidel <args>"`, stdout and stderr into files of `dir`'s
/// parent; status is the exit status, or 128 + the signal that ended the process.
RunResult run_limited(const std::string& limits, const std::string& args, const std::string& tag) {
    const std::string out = work_path(tag + ".out"), err = work_path(tag + ".err");
    const std::string command = limits + "; exec '" + std::string(EXIDEL_CLI_PATH) + "' " + args +
                                " < /dev/null > '" + out + "' 2> '" + err + "'";
    const int raw = std::system(("/bin/sh -c \"" + command + "\"").c_str());
    RunResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

TEST(Faults, AFullDiskIsSaidWithItsReason) {
    // /dev/full answers every write with ENOSPC: a disk that is full from the first byte.
    // (A device is written in place, so there is no temporary to remove here; the file
    // size limit below covers that.)
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
    const std::string input = f64_points(work_path("full_disk.f64"), 2000, 1);
    const RunResult r =
        run_exidel("full_disk", "triangulate '" + input + "' -o /dev/full --format off", "");
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("cannot write '/dev/full': No space left on device"), std::string::npos)
        << r.err;
}

TEST(Faults, AFileSizeLimitStopsTheWriteAndLeavesNothingBehind) {
    // ulimit -f in the shell: the kernel refuses writes past the limit (SIGXFSZ, which
    // exidel ignores, then EFBIG), exactly where a full disk would refuse them. The
    // triangulation (.ele) and its points (.node, written beside it) are both removed.
    const std::string dir = fresh_dir("file_size_limit");
    const std::string input = f64_points(work_path("file_size_limit.f64"), 20000, 2);
    for (const char* out : {"t.off", "t.ele", "t.json"}) {
        // dash counts ulimit -f in 512-byte blocks: 64 KiB, less than any of the outputs.
        const RunResult r =
            run_limited("ulimit -f 128", "triangulate '" + input + "' -o '" + dir + "/" + out + "'",
                        std::string("file_size_limit_") + out);
        EXPECT_EQ(r.status, 1) << out << ": " << r.err;
        EXPECT_NE(r.err.find("File too large"), std::string::npos) << out << ": " << r.err;
        EXPECT_EQ(files_in(dir), std::vector<std::string>{}) << out;
    }
}

TEST(Faults, TooLittleMemoryIsSaidWithTheNeedAndLeavesNothingBehind) {
    if (shadow_memory) {
        GTEST_SKIP() << "a sanitizer's shadow memory does not fit an address-space limit";
    }
    const std::string dir = fresh_dir("memory_limit");
    constexpr std::size_t n = 2'000'000;
    const std::string input = f64_points(work_path("memory_limit.f64"), n, 3);
    // The address space of the process (libraries, stacks, the input) is limited to a
    // range of sizes, from too little for the triangulation to enough. Each run either
    // succeeds or says that memory is short, with the step and its need: never a crash,
    // never a leftover file.
    bool refused = false, succeeded = false;
    for (const int mb : {100, 150, 200, 300, 400, 1200}) {
        const std::string out = dir + "/t" + std::to_string(mb) + ".off";
        const RunResult r = run_limited("ulimit -v " + std::to_string(mb * 1024),
                                        "triangulate '" + input + "' --threads 2 -o '" + out + "'",
                                        "memory_limit_" + std::to_string(mb));
        if (r.status == 0) {
            succeeded = true;
            EXPECT_TRUE(fs::exists(out)) << mb << " MB";
            fs::remove(out);
        } else {
            refused = true;
            EXPECT_EQ(r.status, 1) << mb << " MB: " << r.err;
            EXPECT_NE(r.err.find("exidel: not enough memory for"), std::string::npos)
                << mb << " MB: " << r.err;
        }
        EXPECT_EQ(files_in(dir), std::vector<std::string>{}) << mb << " MB";
    }
    EXPECT_TRUE(refused) << "no limit was too small: the test no longer reaches the fault";
    EXPECT_TRUE(succeeded) << "no limit was large enough";
    // The smallest limit stops the triangulation itself: the message gives its size.
    const RunResult r =
        run_limited("ulimit -v " + std::to_string(100 * 1024),
                    "triangulate '" + input + "' -o '" + dir + "/t.off'", "memory_limit_message");
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("not enough memory for triangulating 2000000 points (needs about "),
              std::string::npos)
        << r.err;
}

TEST(Faults, AnOutputDirectoryRemovedDuringTheRunIsSaidAndLeavesNothing) {
    // The input is a FIFO: exidel creates its temporary output, then blocks opening the
    // input until the test writes it. Meanwhile the test removes the output's directory.
    const std::string dir = fresh_dir("removed_dir");
    const std::string out_dir = dir + "/out";
    fs::create_directories(out_dir);
    const std::string fifo = dir + "/points.fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
    const std::string err_path = dir + "/exidel.err";
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        ::dup2(err, 2);
        ::execl(EXIDEL_CLI_PATH, EXIDEL_CLI_PATH, "triangulate", fifo.c_str(), "--input-format",
                "xy", "-o", (out_dir + "/t.off").c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Wait for the temporary to exist (exidel is then blocked on the FIFO).
    bool pending = false;
    for (int i = 0; i < 1000 && !pending; ++i) {
        for (const std::string& name : files_in(out_dir)) pending |= name.starts_with("t.off.tmp.");
        if (!pending) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_TRUE(pending) << "no temporary output appeared in 10 s";
    fs::remove_all(out_dir);
    {
        std::ofstream points(fifo);
        for (int i = 0; i < 100; ++i)
            points << (i % 10) * 0.5 << ' ' << (i / 10) * 0.25 + 0.01 * i << '\n';
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 1);
    const std::string err = slurp(err_path);
    EXPECT_NE(err.find("cannot write '" + out_dir + "/t.off': No such file or directory"),
              std::string::npos)
        << err;
    EXPECT_FALSE(fs::exists(out_dir));
}

}  // namespace
