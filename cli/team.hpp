// exidel CLI (internal): the processes a command runs on. One process alone, or, when
// exidel was built with MPI and mpirun started it, the ranks of the MPI job (team_mpi.cpp;
// team_solo.cpp when MPI was not found at configure time).
#pragma once

#include <memory>

#include "exidel/research/fuzz.hpp"

namespace exidel::cli {

using research::Team;

/// The team of this process: MPI is initialised only when a launcher's variables say the
/// process is a rank of an MPI job (launched_by_mpi),
/// so a plain `exidel fuzz` never starts MPI. Finalised when the team is destroyed.
/// Throws std::runtime_error when launched as a rank of a job of several ranks by an
/// exidel built without MPI (each rank would otherwise run the whole campaign).
std::unique_ptr<Team> join_team();

/// The number of ranks a launcher's variables announce (1 when none is set).
int launcher_ranks();

/// This process alone (what join_team returns outside an MPI job).
std::unique_ptr<Team> make_solo_team();

/// Whether a launcher's variables are set (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK).
bool launched_by_mpi();

}  // namespace exidel::cli
