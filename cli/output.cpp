#include "output.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <stdexcept>

namespace exidel::cli {

namespace {

// The temporaries the signal handler removes. A handler may only touch lock-free atomics
// and call async-signal-safe functions (unlink, signal, raise), so the paths live in fixed
// buffers and a slot is published by its flag after its path is written.
constexpr std::size_t max_pending = 4;
constexpr std::size_t max_path = 4096;
struct Slot {
    char path[max_path];
    volatile std::sig_atomic_t active;
};
std::array<Slot, max_pending> slots{};
std::mutex slots_mutex;  // between threads that create and remove files, never in the handler

extern "C" void remove_pending_and_reraise(int sig) {
    for (Slot& s : slots) {
        if (s.active) ::unlink(s.path);
    }
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

void install_handlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
            struct sigaction action {};
            action.sa_handler = remove_pending_and_reraise;
            sigemptyset(&action.sa_mask);
            // A signal the shell ignores (nohup, a background job's SIGINT) stays ignored.
            struct sigaction old {};
            ::sigaction(sig, nullptr, &old);
            if (old.sa_handler != SIG_IGN) ::sigaction(sig, &action, nullptr);
        }
    });
}

std::string directory_of(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash == 0 ? 1 : slash);
}

/// The file `path` names once the symbolic links at its end (a link to a link ...) are
/// followed: the output is written through a link, never over it. A relative target is
/// relative to the link's directory; a dangling link names the file it would create.
std::string follow_links(std::string path) {
    for (int hops = 0; hops < 40; ++hops) {  // Linux's own limit (MAXSYMLINKS)
        struct stat st {};
        if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
        std::string target(max_path, '\0');
        const ssize_t n = ::readlink(path.c_str(), target.data(), target.size());
        if (n < 0 || std::size_t(n) >= target.size()) return path;  // then the open reports it
        target.resize(std::size_t(n));
        path = target.starts_with('/') ? target : directory_of(path) + "/" + target;
    }
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(ELOOP));
}

}  // namespace

PendingFile::PendingFile(std::string path)
    : path_(follow_links(std::move(path))), temp_(path_ + ".tmp.XXXXXX") {
    // A device or a pipe (/dev/null, /dev/stdout, a FIFO) is written in place: renaming a
    // temporary over it would replace /dev/null with a regular file.
    struct stat st {};
    if (::stat(path_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        if (S_ISDIR(st.st_mode)) {
            throw std::runtime_error("cannot write '" + path_ + "': " + std::strerror(EISDIR));
        }
        temp_ = path_;
        return;
    }
    if (temp_.size() >= max_path) throw std::runtime_error("output path too long: '" + path_ + "'");
    install_handlers();
    {
        // Claim a slot before the file exists, so that no moment has an unlisted file.
        const std::lock_guard lock(slots_mutex);
        for (std::size_t i = 0; i < max_pending; ++i) {
            if (!slots[i].active) {
                slot_ = static_cast<int>(i);
                break;
            }
        }
        if (slot_ < 0) throw std::logic_error("PendingFile: more than 4 pending output files");
        // mkstemp chooses the name as it creates the file, so the slot can only be
        // published after it: the signals wait (blocked) until both are done.
        sigset_t block, previous;
        sigemptyset(&block);
        for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&block, sig);
        ::pthread_sigmask(SIG_BLOCK, &block, &previous);
        const int fd = ::mkstemp(temp_.data());
        const int error = errno;
        if (fd >= 0) {
            std::memcpy(slots[slot_].path, temp_.c_str(), temp_.size() + 1);
            slots[slot_].active = 1;
        }
        ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
        if (fd < 0) {
            slot_ = -1;
            throw std::runtime_error("cannot create '" + path_ + "' (a temporary file in '" +
                                     directory_of(path_) + "'): " + std::strerror(error));
        }
        // mkstemp creates the file 0600; give the result the permissions a plain open would.
        const mode_t mask = ::umask(0);
        ::umask(mask);
        ::fchmod(fd, 0666 & ~mask);
        ::close(fd);
    }
}

PendingFile::~PendingFile() {
    if (slot_ < 0) return;
    const std::lock_guard lock(slots_mutex);
    slots[slot_].active = 0;
    ::unlink(temp_.c_str());
}

std::ofstream PendingFile::open() const {
    return std::ofstream(temp_, std::ios::binary | std::ios::trunc);
}

void PendingFile::commit() {
    if (in_place()) return;
    if (slot_ < 0) throw std::logic_error("PendingFile: committed twice");
    if (std::rename(temp_.c_str(), path_.c_str()) != 0) {
        throw std::runtime_error("cannot rename the temporary file to '" + path_ +
                                 "': " + std::strerror(errno));
    }
    const std::lock_guard lock(slots_mutex);
    slots[slot_].active = 0;
    slot_ = -1;
}

}  // namespace exidel::cli
