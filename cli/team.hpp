// exidel CLI (internal): the processes a command runs on. One process alone, or, when
// exidel was built with MPI and mpirun started it, the ranks of the MPI job (team_mpi.cpp;
// team_solo.cpp when MPI was not found at configure time).
#pragma once

#include <memory>
#include <utility>

#include "exidel/research/fuzz.hpp"

namespace exidel::cli {

using research::Team;

/// The team of this process, owned while the membership lives: Team::solo(), or an MPI
/// team that finalises MPI when destroyed.
class Membership {
public:
    Membership() = default;
    explicit Membership(std::unique_ptr<Team> owned)
        : owned_(std::move(owned)), team_(owned_.get()) {}
    Team& team() { return *team_; }

private:
    std::unique_ptr<Team> owned_;
    Team* team_ = &Team::solo();
};

/// The team of this process: MPI is initialised only when a launcher's variables say the
/// process is a rank of an MPI job (launched_by_mpi),
/// so a plain `exidel fuzz` never starts MPI. Finalised when the team is destroyed.
/// Throws std::runtime_error when launched as a rank of a job of several ranks by an
/// exidel built without MPI (each rank would otherwise run the whole campaign).
Membership join_team();

/// The number of ranks a launcher's variables announce (1 when none is set).
int launcher_ranks();

/// Whether a launcher's variables are set (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK).
bool launched_by_mpi();

}  // namespace exidel::cli
