// exidel CLI (internal): output files that appear whole or not at all.
//
// A PendingFile is a temporary file next to its destination ("PATH.tmp.XXXXXX"), created
// when the command starts, so that an unwritable directory is reported before minutes
// of reading and triangulating, and renamed over PATH by commit() once everything
// succeeded. It is removed when the command fails, returns early or throws (destructor),
// and when the process is interrupted by SIGINT, SIGTERM or SIGHUP (a handler that
// unlinks every pending temporary, then lets the signal end the process as it would
// have: the exit status still says "killed by signal N"). A path that exists and is not a
// regular file (/dev/null, a FIFO) is written directly: it has no partial state to hide,
// and a rename would replace the device with a file. A symbolic link is written through:
// the temporary file goes next to the file the link names, and the link stays a link.
#pragma once

#include <iosfwd>
#include <string>

namespace exidel::cli {

class PendingFile {
public:
    /// Creates the temporary file next to `path`. Throws std::runtime_error with the
    /// system's reason when it cannot ("cannot create a file in 'DIR': Permission denied").
    explicit PendingFile(std::string path);
    ~PendingFile();
    PendingFile(const PendingFile&) = delete;
    PendingFile& operator=(const PendingFile&) = delete;

    /// The file written: the path given, with symbolic links at its end followed.
    const std::string& path() const noexcept { return path_; }
    /// True for a device or a pipe (/dev/null, a FIFO), written in place, not through a
    /// temporary file.
    bool in_place() const noexcept { return temp_ == path_; }

    /// Opens the temporary file for writing (truncated), binary.
    std::ofstream open() const;
    /// Renames the temporary file over path(). Throws std::runtime_error on failure.
    void commit();

private:
    std::string path_;
    std::string temp_;
    int slot_ = -1;  // its place in the signal handler's list
};

}  // namespace exidel::cli
