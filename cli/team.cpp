// exidel CLI: what team_solo.cpp and team_mpi.cpp share.
#include <cstdlib>

#include "team.hpp"

namespace exidel::cli {

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
