// exidel CLI: what team_solo.cpp and team_mpi.cpp share.
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "team.hpp"

namespace exidel::cli {

namespace {

/// Team::solo() behind the unique_ptr join_team returns (never deleted itself).
class Solo final : public Team {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    std::vector<std::string> gather(const std::string& mine) override { return Team::solo().gather(mine); }
    double max(double value) override { return Team::solo().max(value); }
};

}  // namespace

std::unique_ptr<Team> make_solo_team() { return std::make_unique<Solo>(); }

int launcher_ranks() {
    // Open MPI's mpirun, then the PMI variable of other launchers (srun, hydra).
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
        if (const char* v = std::getenv(name)) {
            const int n = std::atoi(v);
            if (n >= 1) return n;
        }
    }
    return 1;
}

bool launched_by_mpi() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
        if (std::getenv(name)) return true;
    }
    return false;
}

}  // namespace exidel::cli
