// End-to-end tests of `exidel fuzz predicates`: counts, determinism over threads,
// disagreements that replay through `exidel predicate`, checkpoints and resuming, errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "run_binary.hpp"

namespace {

using exidel::cli_test::run_exidel;
using exidel::cli_test::work_path;
using Json = nlohmann::json;

/// The summary without the members that differ between runs of one campaign.
Json timeless(Json j) {
    j.erase("seconds");
    j.erase("run");
    return j;
}

Json read_json(const std::string& path) { return Json::parse(exidel::cli_test::slurp(path)); }

/// Standard output without its last line (the timing line).
std::string without_last_line(const std::string& s) {
    const std::size_t end = s.rfind('\n', s.size() >= 2 ? s.size() - 2 : 0);
    return end == std::string::npos ? std::string() : s.substr(0, end + 1);
}

std::string fuzz(const std::string& options, const std::string& name) {
    return "fuzz predicates --no-progress --checkpoint '" + work_path(name + ".ckpt") +
           "' --summary '" + work_path(name + ".json") + "' " + options;
}

std::string fuzz_t(const std::string& options, const std::string& name) {
    return "fuzz triangulations --no-progress --checkpoint '" + work_path(name + ".ckpt") +
           "' --summary '" + work_path(name + ".json") + "' " + options;
}

TEST(ExidelFuzz, AdaptiveAgreesWithExactAndEveryQueryIsCounted) {
    const auto r = run_exidel("fuzz_ok", fuzz("-n 26000 --seed 7 -j 2", "ok"), "");
    ASSERT_EQ(r.status, 0) << r.err;
    const Json j = read_json(work_path("ok.json"));
    EXPECT_EQ(j["queries"], 26000);
    EXPECT_EQ(j["disagreements"], 0);
    EXPECT_EQ(j["kernel"], "adaptive");
    EXPECT_EQ(j["reference"], "exact");
    ASSERT_EQ(j["families"].size(), 13u);
    std::uint64_t sum = 0;
    for (const auto& [name, f] : j["families"].items()) {
        std::uint64_t per_predicate = 0;
        ASSERT_EQ(f["predicates"].size(), 4u) << name;
        for (const auto& [p, n] : f["predicates"].items())
            per_predicate += n["queries"].get<std::uint64_t>();
        EXPECT_EQ(per_predicate, f["queries"].get<std::uint64_t>()) << name;
        EXPECT_GT(f["queries"].get<std::uint64_t>(), 1000u)
            << name;  // 102 blocks of 256, families in turn
        sum += f["queries"].get<std::uint64_t>();
    }
    EXPECT_EQ(sum, 26000u);
    EXPECT_TRUE(j["reported"].empty());
    EXPECT_GT(j["seconds"].get<double>(), 0.0);
    EXPECT_EQ(j["run"]["threads_per_rank"], 2);
    EXPECT_NE(r.out.find("# 26000 queries, 0 disagreements (adaptive against exact)"),
              std::string::npos)
        << r.out;
    // The checkpoint of a finished campaign is removed.
    EXPECT_FALSE(std::filesystem::exists(work_path("ok.ckpt")));
}

TEST(ExidelFuzz, DisagreementsAreShrunkAndReplay) {
    const auto r = run_exidel(
        "fuzz_double",
        fuzz("-k double -n 3000 --families near --predicates orient2d,incircle --reports 4 -j 2",
             "double"),
        "");
    ASSERT_EQ(r.status, 1) << r.err;  // disagreements found
    const Json j = read_json(work_path("double.json"));
    ASSERT_GT(j["disagreements"].get<std::uint64_t>(), 4u);
    ASSERT_EQ(j["reported"].size(), 4u);
    std::uint64_t previous = 0;
    for (const Json& d : j["reported"]) {
        EXPECT_GE(d["query"].get<std::uint64_t>(), previous);  // the first ones, in query order
        previous = d["query"].get<std::uint64_t>();
        EXPECT_NE(d["kernel_sign"], d["reference_sign"]);
        EXPECT_NE(d["shrunk_kernel_sign"], d["shrunk_reference_sign"]);
    }
    // Standard output is `exidel predicate` input: the shrunk queries, and only they.
    const auto with_double = run_exidel("fuzz_replay_double", "predicate -k double", r.out);
    const auto with_exact = run_exidel("fuzz_replay_exact", "predicate -k exact", r.out);
    ASSERT_EQ(with_double.status, 0) << with_double.err;
    ASSERT_EQ(with_exact.status, 0) << with_exact.err;
    std::string expected_double, expected_exact;
    for (const Json& d : j["reported"]) {
        expected_double += std::to_string(d["shrunk_kernel_sign"].get<int>()) + "\n";
        expected_exact += std::to_string(d["shrunk_reference_sign"].get<int>()) + "\n";
    }
    EXPECT_EQ(with_double.out, expected_double);
    EXPECT_EQ(with_exact.out, expected_exact);
    // The query as drawn replays too (it is in the summary and in the comment line).
    std::string drawn;
    for (const Json& d : j["reported"]) drawn += d["line"].get<std::string>() + "\n";
    EXPECT_NE(run_exidel("fuzz_drawn_double", "predicate -k double", drawn).out,
              run_exidel("fuzz_drawn_exact", "predicate -k exact", drawn).out);
}

TEST(ExidelFuzz, TheSameCampaignWhateverTheThreads) {
    const auto one =
        run_exidel("fuzz_j1", fuzz("-k long-double -n 9000 --seed 3 -j 1 --reports 3", "j1"), "");
    const auto two =
        run_exidel("fuzz_j2", fuzz("-k long-double -n 9000 --seed 3 -j 2 --reports 3", "j2"), "");
    ASSERT_EQ(one.status, two.status) << one.err << two.err;
    EXPECT_EQ(timeless(read_json(work_path("j1.json"))), timeless(read_json(work_path("j2.json"))));
    EXPECT_EQ(without_last_line(one.out), without_last_line(two.out));
    // Another seed draws other queries.
    ASSERT_NE(
        run_exidel("fuzz_seed", fuzz("-k long-double -n 9000 --seed 4 --reports 3", "seed4"), "")
            .status,
        2);
    EXPECT_NE(timeless(read_json(work_path("seed4.json"))),
              timeless(read_json(work_path("j1.json"))));
}

TEST(ExidelFuzz, AnInterruptedCampaignResumes) {
    namespace fs = std::filesystem;
    const std::string options =
        "-k double -n 40000 --families kettner,lattice_circle --reports 5 -j 2";
    const auto whole = run_exidel("fuzz_whole", fuzz(options + " --keep-checkpoint", "whole"), "");
    ASSERT_EQ(whole.status, 1) << whole.err;
    const fs::path dir = work_path("whole.ckpt");
    ASSERT_TRUE(fs::exists(dir / "campaign"));
    // The interruption: some stripes never finished, one was cut short while written.
    std::vector<fs::path> stripes;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.path().filename().string().starts_with("stripe-")) stripes.push_back(e.path());
    }
    ASSERT_EQ(stripes.size(), 16u);
    std::sort(stripes.begin(), stripes.end());
    for (std::size_t i = 0; i < stripes.size(); i += 3) fs::remove(stripes[i]);
    fs::resize_file(stripes[1], fs::file_size(stripes[1]) / 2);

    // Without --resume the checkpoint is not overwritten.
    const auto refused = run_exidel(
        "fuzz_refused",
        "fuzz predicates --no-progress --checkpoint '" + dir.string() + "' " + options, "");
    EXPECT_EQ(refused.status, 2);
    EXPECT_NE(refused.err.find("--resume continues it"), std::string::npos) << refused.err;
    // Another campaign cannot resume it.
    const auto other = run_exidel("fuzz_other",
                                  "fuzz predicates --no-progress --resume --checkpoint '" +
                                      dir.string() + "' " + options + " --seed 5",
                                  "");
    EXPECT_EQ(other.status, 2);
    EXPECT_NE(
        other.err.find("is of another campaign (it has 'seed 20250704', this run has 'seed 5')"),
        std::string::npos)
        << other.err;

    const auto resumed =
        run_exidel("fuzz_resumed",
                   "fuzz predicates --no-progress --resume --checkpoint '" + dir.string() +
                       "' --summary '" + work_path("resumed.json") + "' " + options,
                   "");
    ASSERT_EQ(resumed.status, 1) << resumed.err;
    const Json a = read_json(work_path("whole.json")), b = read_json(work_path("resumed.json"));
    EXPECT_EQ(timeless(a), timeless(b));
    EXPECT_EQ(without_last_line(whole.out), without_last_line(resumed.out));
    // 16 stripes of 10 blocks of 256 queries (the last stripe 1600): 6 removed (the last
    // among them) and one cut, so 9 whole ones came from the checkpoint.
    EXPECT_EQ(b["run"]["resumed_queries"], 9 * 2560);
    EXPECT_FALSE(fs::exists(dir));  // finished: removed
}

TEST(ExidelFuzz, BadOptionsAreUsageErrors) {
    struct Case {
        const char* args;
        const char* message;
    };
    for (const Case& c :
         {Case{"fuzz predicates -n 0", "--queries takes a whole number from 1 to 2^62"},
          Case{"fuzz predicates -n 1.5e3x", "--queries takes a whole number"},
          Case{"fuzz predicates -n 2.5", "--queries takes a whole number"},
          Case{"fuzz predicates -k nope", "unknown kernel"},
          Case{"fuzz predicates --reference mpfr:1", "mpfr"},
          Case{"fuzz predicates --families nowhere", "unknown point family 'nowhere'"},
          Case{"fuzz predicates --predicates orient3d", "unknown predicate 'orient3d'"},
          Case{"fuzz predicates --no-checkpoint --resume", "--no-checkpoint with --resume"},
          Case{"fuzz predicates --resume --checkpoint nowhere-at-all", "no campaign to resume"},
          Case{"fuzz triangles", "unknown campaign 'triangles' (predicates or triangulations)"}}) {
        const auto r = run_exidel("fuzz_bad", c.args, "");
        EXPECT_EQ(r.status, 2) << c.args;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    }
    const auto help = run_exidel("fuzz_help", "fuzz predicates --help", "");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("mpirun -np R exidel fuzz predicates"), std::string::npos);
}

TEST(ExidelFuzz, AQueryCountInExponentForm) {
    const auto r = run_exidel("fuzz_exp", fuzz("-n 2.5e3 --families uniform", "exp"), "");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read_json(work_path("exp.json"))["queries"], 2500);
    EXPECT_EQ(read_json(work_path("exp.json"))["families"].size(), 1u);
}

// ---------------------------------------------------------------------------------
// exidel fuzz triangulations

TEST(ExidelFuzzTriangulations, EveryMethodCertifiesWithTheAdaptiveKernel) {
    const auto one = run_exidel("fuzzt_j1", fuzz_t("--sets 52 --sizes 3-40 -j 1", "t1"), "");
    ASSERT_EQ(one.status, 0) << one.err;
    const Json j = read_json(work_path("t1.json"));
    const std::size_t methods = j["methods"].size();
    EXPECT_GE(methods, 9u);  // the external algorithm in three orders, six others
    EXPECT_EQ(j["policies"].size(), 2u);
    EXPECT_EQ(j["triangulations"], 52 * methods * 2);
    EXPECT_EQ(j["outcomes"]["delaunay"], j["triangulations"]);
    EXPECT_EQ(j["wrong"], 0);
    EXPECT_EQ(j["problems"], 0);
    for (const auto& [name, f] : j["families"].items())
        EXPECT_EQ(f["triangulations"], 4 * methods * 2) << name;
    for (const auto& [name, m] : j["methods"].items())
        EXPECT_EQ(m["triangulations"], 52 * 2) << name;
    EXPECT_TRUE(j["reported"].empty());
    // The same campaign on two threads.
    const auto two = run_exidel("fuzzt_j2", fuzz_t("--sets 52 --sizes 3-40 -j 2", "t2"), "");
    ASSERT_EQ(two.status, 0) << two.err;
    EXPECT_EQ(timeless(j), timeless(read_json(work_path("t2.json"))));
    EXPECT_EQ(without_last_line(one.out), without_last_line(two.out));
}

/// The command of a fixture's "reproduce:" header line, with FILE replaced by its path.
std::string replay_command(const std::string& path) {
    std::istringstream in(exidel::cli_test::slurp(path));
    const std::string prefix = "# reproduce: exidel ";
    for (std::string line; std::getline(in, line);) {
        if (!line.starts_with(prefix)) continue;
        std::string command = line.substr(prefix.size());
        command.replace(command.find("FILE"), 4, "'" + path + "'");
        return command;
    }
    return {};
}

TEST(ExidelFuzzTriangulations, WrongOutcomesOfTheDoubleKernelBecomeFixturesThatReplay) {
    const std::string out = work_path("t-fixtures");
    std::filesystem::remove_all(out);
    const auto r =
        run_exidel("fuzzt_double",
                   fuzz_t("-k double --families near_lattice_circle,near_rounded_circle --sets 60 "
                          "--sizes 20-60 --reports 3 --out '" +
                              out + "'",
                          "tdouble"),
                   "");
    const Json j = read_json(work_path("tdouble.json"));
    ASSERT_GT(j["wrong"].get<std::uint64_t>(), 3u) << r.out;
    // An inexact kernel's wrong outcomes are expected; only a guard (a hang) is a problem.
    EXPECT_EQ(j["problems"], j["outcomes"]["guard"]);
    EXPECT_EQ(r.status, j["problems"] == 0 ? 0 : 1) << r.err;
    ASSERT_EQ(j["reported"].size(), 3u);
    for (const Json& f : j["reported"]) {
        const std::string path = out + "/" + f["file"].get<std::string>();
        ASSERT_TRUE(exidel::cli_test::exists(path)) << path;
        EXPECT_LE(f["shrunk_points"].get<std::size_t>(), f["points"].get<std::size_t>());
        EXPECT_EQ(f["shrunk_outcome"], f["outcome"]);
        // The fixture's own command reproduces the wrong outcome (exit status 1: a failed
        // triangulation, or --certify's finding), and the exact kernel certifies it.
        const std::string command = replay_command(path);
        ASSERT_FALSE(command.empty()) << path;
        EXPECT_EQ(run_exidel("fuzzt_replay", command, "").status, 1) << command;
        std::string exact = command;
        exact.replace(exact.find("--kernel double"), 15, "--kernel exact");
        EXPECT_EQ(run_exidel("fuzzt_replay_exact", exact, "").status, 0) << exact;
    }
}

TEST(ExidelFuzzTriangulations, BadOptionsAreUsageErrors) {
    struct Case {
        const char* args;
        const char* message;
    };
    for (const Case& c :
         {Case{"fuzz triangulations --sizes 10-5", "1 <= MIN <= MAX"},
          Case{"fuzz triangulations --sizes 0-5", "1 <= MIN <= MAX"},
          Case{"fuzz triangulations --sizes ten", "--sizes takes MIN-MAX"},
          Case{"fuzz triangulations --sizes 3-1000000", "up to 100000 points"},
          Case{"fuzz triangulations --incircle circle", "--incircle takes determinant, cosine"},
          Case{"fuzz triangulations --algorithms quickhull", "quickhull"},
          Case{"fuzz triangulations --orders spiral", "spiral"},
          Case{"fuzz triangulations -n 0", "--sets takes a whole number"},
          Case{"fuzz triangulations --kernel mpfr:0", "mpfr"}}) {
        const auto r = run_exidel("fuzzt_bad", c.args, "");
        EXPECT_EQ(r.status, 2) << c.args;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    }
    const auto help = run_exidel("fuzzt_help", "fuzz triangulations --help", "");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("guard (more than 64 n^2 + 10^6 predicate calls"), std::string::npos);
    const auto overview = run_exidel("fuzz_overview", "fuzz --help", "");
    EXPECT_EQ(overview.status, 0);
    EXPECT_NE(overview.out.find("exidel fuzz triangulations [options]"), std::string::npos);
}

}  // namespace
