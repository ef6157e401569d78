// exidel CLI: `exidel study` and `exidel fuzz` when exidel::research was not built (it needs
// RapidCheck and libpng; see lib/research/CMakeLists.txt). Says so instead of being absent.
#include <iostream>

#include "commands.hpp"

namespace exidel::cli {

int study_command(std::span<const std::string_view>) {
    std::cerr << "exidel study: this exidel was built without exidel::research (it needs "
                 "RapidCheck and libpng: apt-get install librapidcheck-dev libpng-dev, then "
                 "rebuild)\n";
    return exit_failure;
}

int fuzz_command(std::span<const std::string_view>) {
    std::cerr << "exidel fuzz: this exidel was built without exidel::research (it needs "
                 "RapidCheck and libpng: apt-get install librapidcheck-dev libpng-dev, then "
                 "rebuild)\n";
    return exit_failure;
}

}  // namespace exidel::cli
