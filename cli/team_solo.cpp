// exidel CLI: the team of an exidel built without MPI (team.hpp).
#include <stdexcept>
#include <string>

#include "team.hpp"

namespace exidel::cli {

Membership join_team() {
    if (const int ranks = launcher_ranks(); ranks > 1) {
        throw std::runtime_error(
            "started as one of " + std::to_string(ranks) +
            " MPI ranks, but this exidel was built without MPI (Debian: apt-get install "
            "libopenmpi-dev openmpi-bin, then configure and build again)");
    }
    return {};
}

}  // namespace exidel::cli
