// Helpers of the end-to-end tests of the built `exidel` binary: files in the test work
// directory (EXIDEL_CLI_TEST_DIR) and one run of the binary (EXIDEL_CLI_PATH).
#pragma once

#include <dirent.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace exidel::cli_test {

struct RunResult {
    int status = -1;
    std::string out;
    std::string err;
};

inline std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

inline bool exists(const std::string& path) { return std::ifstream(path).good(); }

inline std::string work_path(const std::string& name) {
    return std::string(EXIDEL_CLI_TEST_DIR) + "/" + name;
}

inline std::string write_file(const std::string& name, const std::string& content) {
    const std::string path = work_path(name);
    std::ofstream(path, std::ios::binary) << content;
    return path;
}

/// Files in the work directory whose name contains `part` (leftover temporaries).
inline std::vector<std::string> files_containing(const std::string& part) {
    std::vector<std::string> found;
    DIR* d = opendir(EXIDEL_CLI_TEST_DIR);
    if (!d) return found;
    while (const dirent* e = readdir(d)) {
        const std::string name = e->d_name;
        if (name.find(part) != std::string::npos) found.push_back(name);
    }
    closedir(d);
    return found;
}

/// Runs `exidel ARGS` (already shell-quoted where needed) with stdin from `input`. Each
/// call gets its own files, named `<prefix><n>.in/.out/.err` in the work directory.
inline RunResult run_exidel(const std::string& prefix, const std::string& args,
                            const std::string& input) {
    static int counter = 0;
    const std::string base = work_path(prefix + std::to_string(counter++));
    const std::string in = base + ".in";
    std::ofstream(in, std::ios::binary) << input;
    const std::string command = std::string("'") + EXIDEL_CLI_PATH + "' " + args + " < '" + in +
                                "' > '" + base + ".out' 2> '" + base + ".err'";
    const int raw = std::system(command.c_str());
    RunResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(base + ".out");
    r.err = slurp(base + ".err");
    return r;
}

}  // namespace exidel::cli_test
