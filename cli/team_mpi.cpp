// exidel CLI: the team of an exidel built with MPI (team.hpp). Four collective calls and
// nothing else: the campaign's layout is fixed in advance (fuzz.hpp), so ranks only meet
// at the start (the checkpoint check), and at the end to hand their counts to rank 0.
#include <mpi.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "team.hpp"

namespace exidel::cli {

namespace {

void check(int status, const char* what) {
    if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

class MpiTeam final : public Team {
public:
    MpiTeam() {
        int initialised = 0;
        check(MPI_Initialized(&initialised), "MPI_Initialized");
        if (!initialised) check(MPI_Init(nullptr, nullptr), "MPI_Init");
        // Errors come back as status codes (check above) rather than aborting the job
        // inside MPI, so that they reach the user as exidel's message.
        MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
        check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
        check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
    }
    ~MpiTeam() override { MPI_Finalize(); }
    MpiTeam(const MpiTeam&) = delete;
    MpiTeam& operator=(const MpiTeam&) = delete;

    int rank() const override { return rank_; }
    int size() const override { return size_; }

    std::vector<std::string> gather(const std::string& mine) override {
        int length = int(mine.size());
        std::vector<int> lengths(rank_ == 0 ? std::size_t(size_) : 0);
        check(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD),
              "MPI_Gather");
        std::vector<int> offsets(lengths.size());
        std::string all;
        if (rank_ == 0) {
            long long total = 0;
            for (std::size_t r = 0; r < lengths.size(); ++r) {
                offsets[r] = int(total);
                total += lengths[r];
            }
            if (total > 2'000'000'000)
                throw std::runtime_error("MPI: the ranks' results exceed 2 GB");
            all.resize(std::size_t(total));
        }
        check(MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                          MPI_CHAR, 0, MPI_COMM_WORLD),
              "MPI_Gatherv");
        std::vector<std::string> parts;
        for (std::size_t r = 0; r < lengths.size(); ++r) {
            parts.push_back(all.substr(std::size_t(offsets[r]), std::size_t(lengths[r])));
        }
        return parts;
    }

    double max(double value) override {
        double result = 0;
        check(MPI_Allreduce(&value, &result, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD),
              "MPI_Allreduce");
        return result;
    }

    void fail() override { MPI_Abort(MPI_COMM_WORLD, 1); }

private:
    int rank_ = 0, size_ = 1;
};

}  // namespace

Membership join_team() {
    if (!launched_by_mpi()) return {};
    return Membership(std::make_unique<MpiTeam>());
}

}  // namespace exidel::cli
