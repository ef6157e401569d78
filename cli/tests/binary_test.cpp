// End-to-end tests of the built `exidel` binary: exit statuses, error line numbers, the
// streaming contract, every kernel, and agreement of the exact kernels on a generated
// near-degenerate file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "exidel/predicates/build_info.hpp"
#include "run_binary.hpp"

namespace {

using namespace exidel::cli_test;

RunResult run(const std::string& args, const std::string& input = "") {
    return run_exidel("run", args, input);
}

const std::vector<std::string> all_kernels = {"double",    "long-double", "adaptive", "exact",
                                              "exact-cpp", "mpfr:53",     "mpfr:300"};

TEST(ExidelBinary, TopLevelHelpAndUsage) {
    const RunResult help = run("--help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("usage: exidel <command>"), std::string::npos);
    EXPECT_NE(help.out.find("predicate"), std::string::npos);
    EXPECT_EQ(run("").status, 2);
    const RunResult unknown = run("frobnicate");
    EXPECT_EQ(unknown.status, 2);
    EXPECT_NE(unknown.err.find("unknown command 'frobnicate'"), std::string::npos);
    // --version says which exidel, built how, with which kernels.
    const RunResult version = run("--version");
    EXPECT_EQ(version.status, 0);
    const exidel::BuildInfo& b = exidel::build_info();
    EXPECT_EQ(
        version.out.rfind(
            "exidel " + std::string(b.version) + " (commit " + std::string(b.commit) + ")\n", 0),
        0u)
        << version.out;
    for (const char* part :
         {"compiler: ", "-ffp-contract=off", "GMP ", "MPFR ", "Boost ",
          "long double: ", "kernels: double long-double adaptive", "algorithms: external"}) {
        EXPECT_NE(version.out.find(part), std::string::npos) << part << "\n" << version.out;
    }
}

TEST(ExidelBinary, PredicateHelp) {
    const RunResult help = run("predicate --help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("usage: exidel predicate"), std::string::npos);
    EXPECT_NE(help.out.find("incircle_cosine"), std::string::npos);
    EXPECT_TRUE(help.err.empty());
}

TEST(ExidelBinary, BadOptionsExitTwoWithUsage) {
    for (const char* args : {"predicate --kernel", "predicate --kernel fast",
                             "predicate --kernel=mpfr:1", "predicate --frob",
                             "predicate a.txt b.txt", "predicate -i a.txt b.txt", "predicate -i"}) {
        const RunResult r = run(args, "orient2d 0 0 1 0 0 1\n");
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_NE(r.err.find("usage: exidel predicate"), std::string::npos) << args;
        EXPECT_TRUE(r.out.empty()) << args;
    }
}

TEST(ExidelBinary, MissingFileIsAFailure) {
    const RunResult r = run("predicate " + work_path("does-not-exist.txt"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("cannot open"), std::string::npos);
}

TEST(ExidelBinary, SignsCommentsAndHexFloats) {
    const std::string input =
        "# header comment\n"
        "\n"
        "orient2d 0 0 1 0 0 1          # counter-clockwise\n"
        "orient2d 0 0 0x1p0 0 0x0p0 -0X1P+0   # clockwise\n"
        "\t orient2d 0 0 1 1 2 2\n"
        "incircle 0 0 1 0 0 1 0.25 0.25\n"
        "incircle 0 0 1 0 0 1 1 1\n"
        "incircle 0 0 1 0 0 1 2 2\r\n"
        "incircle_cosine 0 0 1 0 0.5 1 0.5 -0.1\n"
        "incircle_cosine 0 0 1 0 0.5 1 0.5 -2\n"
        "compare_distance 0 0 3 4 5 0   # equally far: 0\n"
        "compare_distance 0.5 0.5 0x1p-20 0 1 1\n";
    const std::string expected = "1\n-1\n0\n1\n0\n-1\n1\n-1\n0\n-1\n";
    for (const std::string& k : all_kernels) {
        const RunResult r = run("predicate --kernel " + k, input);
        EXPECT_EQ(r.status, 0) << k << ": " << r.err;
        EXPECT_EQ(r.out, expected) << k;
        EXPECT_TRUE(r.err.empty()) << k;
    }
}

TEST(ExidelBinary, InputFromFileStdinAndDashAgree) {
    const std::string input = "orient2d 0 0 1 0 0 1\nincircle 0 0 1 0 0 1 3 3\n";
    const std::string path = write_file("small.txt", input);
    const std::string expected = "1\n-1\n";
    EXPECT_EQ(run("predicate " + path).out, expected);
    EXPECT_EQ(run("predicate -i " + path).out, expected);
    EXPECT_EQ(run("predicate --input=" + path).out, expected);
    EXPECT_EQ(run("predicate", input).out, expected);
    EXPECT_EQ(run("predicate -", input).out, expected);
    EXPECT_EQ(run("predicate -k exact -i -", input).out, expected);
}

TEST(ExidelBinary, ErrorNamesTheLineAndStopsOutput) {
    struct Case {
        std::string bad_line;
        std::string reason;
    };
    const std::vector<Case> cases = {
        {"orient2d 0 0 1 0 nan 1", "not a finite number"},
        {"orient2d 0 0 1 0 inf 1", "not a finite number"},
        {"orient2d 0 0 1 0 1e400 1", "outside the range"},
        {"orient2d 0 0 1 0 0", "takes 6 coordinates, got 5"},
        {"incircle 0 0 1 0 0 1 1", "takes 8 coordinates, got 7"},
        {"orient3d 0 0 1 0 0 1", "orient3d takes 12 coordinates, got 6"},
        {"insphere 0 0 0 1 0 0 0 1 0 0 0 -1 0 0 inf", "coordinate 15: 'inf' is not a finite"},
        {"orient4d 0 0 1 0 0 1", "unknown predicate 'orient4d'"},
        {"orient2d 0 0 1 0 0x1q3 1", "not a number"},
    };
    for (const Case& c : cases) {
        const std::string input =
            "# comment\n"
            "orient2d 0 0 1 0 0 1\n"
            "\n"
            "incircle 0 0 1 0 0 1 2 2\n"
            "   # another comment\n"
            "orient2d 0 0 1 0 0 -1\n" +
            c.bad_line + "\n" + "orient2d 0 0 1 0 0 1\n";
        const std::string path = write_file("bad.txt", input);
        const RunResult r = run("predicate " + path);
        EXPECT_EQ(r.status, 1) << c.bad_line;
        EXPECT_EQ(r.out, "1\n-1\n-1\n") << c.bad_line;
        EXPECT_EQ(r.err.rfind("exidel: line 7: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(c.reason), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

// Near-degenerate queries written as exact hexadecimal floats: Kettner et al.'s orientation
// configuration moved over a grid of ulps, a lattice circle nudged by ulps, and the same
// circle probed with the cosine form across a diagonal.
std::string near_degenerate_file() {
    std::string s;
    char buf[512];
    const auto hex_point = [&](double x, double y) {
        std::snprintf(buf, sizeof buf, " %a %a", x, y);
        s += buf;
    };
    const auto ulps = [](double v, int k) {
        for (; k > 0; --k) v = std::nextafter(v, INFINITY);
        for (; k < 0; ++k) v = std::nextafter(v, -INFINITY);
        return v;
    };
    for (int i = 0; i < 24; ++i) {
        for (int j = 0; j < 24; ++j) {
            s += "orient2d";
            hex_point(ulps(0.5, i), ulps(0.5, j));
            hex_point(12, 12);
            hex_point(24, 24);
            s += '\n';
        }
    }
    // Lattice points of the circle of radius 5 about the origin, shifted by (0.1, 0.3):
    // the rounding of the shift leaves them nearly (not exactly) cocircular.
    const double pts[][2] = {{3, 4}, {-4, 3}, {-3, -4}, {4, -3}, {5, 0}, {0, -5}};
    const auto shifted = [](double v, double by) { return v + by; };
    std::mt19937_64 rng(20250101);
    std::uniform_int_distribution<int> ulp(-2, 2);
    for (int n = 0; n < 400; ++n) {
        const auto& a = pts[n % 6];
        const auto& b = pts[(n + 2) % 6];
        const auto& c = pts[(n + 1) % 6];
        const auto& d = pts[(n + 4) % 6];
        for (const char* pred : {"incircle", "incircle_cosine"}) {
            s += pred;
            hex_point(shifted(a[0], 0.1), shifted(a[1], 0.3));
            hex_point(shifted(b[0], 0.1), shifted(b[1], 0.3));
            hex_point(shifted(c[0], 0.1), shifted(c[1], 0.3));
            hex_point(ulps(shifted(d[0], 0.1), ulp(rng)), ulps(shifted(d[1], 0.3), ulp(rng)));
            s += '\n';
        }
    }
    return s;
}

TEST(ExidelBinary, ExactKernelsAgreeOnNearDegenerateFile) {
    const std::string path = write_file("near-degenerate.txt", near_degenerate_file());
    const RunResult exact = run("predicate --kernel exact " + path);
    ASSERT_EQ(exact.status, 0) << exact.err;
    // The file must exercise every sign, or agreement would prove little.
    for (const char* sign : {"-1\n", "0\n", "\n1\n"}) {
        EXPECT_NE(exact.out.find(sign), std::string::npos) << sign;
    }
    // Frexp exponents of the coordinates span at most 6 within a query (0.1 .. 5.3, 0.5 ..
    // 24), so b = 53 + 6 and 8b + 13 = 485 bits make the MPFR
    // kernel exact on every line (proofs/bitcounts.md gives 8b + 12; one spare bit).
    for (const char* k : {"adaptive", "exact-cpp", "mpfr:485"}) {
        const RunResult r = run(std::string("predicate --kernel ") + k + " " + path);
        EXPECT_EQ(r.status, 0) << k << ": " << r.err;
        EXPECT_EQ(r.out, exact.out) << k;
    }
    // The default kernel is adaptive.
    EXPECT_EQ(run("predicate " + path).out, exact.out);
}

}  // namespace
