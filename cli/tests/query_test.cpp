// Unit tests of the `exidel predicate` text format (cli/query.hpp).
#include "query.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/registry.hpp"

namespace exidel::cli {
namespace {

double parsed(std::string_view text) {
    const ParsedNumber n = parse_double(text);
    EXPECT_TRUE(n.value.has_value()) << text << ": " << n.error;
    EXPECT_EQ(n.value.has_value(), n.error.empty());
    return n.value.value_or(std::numeric_limits<double>::quiet_NaN());
}

std::string rejected(std::string_view text) {
    const ParsedNumber n = parse_double(text);
    EXPECT_FALSE(n.value.has_value()) << text << " parsed as " << n.value.value_or(0);
    EXPECT_FALSE(n.error.empty()) << text;
    return n.error;
}

TEST(ParseDouble, DecimalIsCorrectlyRounded) {
    EXPECT_EQ(parsed("0.1"), 0.1);
    EXPECT_EQ(parsed("-2.5"), -2.5);
    EXPECT_EQ(parsed("+3"), 3.0);
    EXPECT_EQ(parsed("1e10"), 1e10);
    EXPECT_EQ(parsed("1E-3"), 1e-3);
    EXPECT_EQ(parsed(".5"), 0.5);
    EXPECT_EQ(parsed("5."), 5.0);
    EXPECT_EQ(parsed("17.300000000000001"), 17.300000000000001);
    // Halfway between 1 and the next double, one digit past: must round up, not truncate.
    EXPECT_EQ(parsed("1.00000000000000011102230246251565404236316680908203126"),
              std::nextafter(1.0, 2.0));
    // Exactly halfway: ties to even (1.0).
    EXPECT_EQ(parsed("1.00000000000000011102230246251565404236316680908203125"), 1.0);
    EXPECT_EQ(parsed("1.7976931348623157e308"), std::numeric_limits<double>::max());
    EXPECT_TRUE(std::signbit(parsed("-0")));
}

TEST(ParseDouble, HexFloats) {
    EXPECT_EQ(parsed("0x1.8p-3"), 0.1875);
    EXPECT_EQ(parsed("-0X1P+4"), -16.0);
    EXPECT_EQ(parsed("+0x10"), 16.0);
    EXPECT_EQ(parsed("0x.8"), 0.5);
    EXPECT_EQ(parsed("0x1.fffffffffffffp+1023"), std::numeric_limits<double>::max());
    EXPECT_EQ(parsed("0x1p-1074"), std::numeric_limits<double>::denorm_min());
    EXPECT_EQ(parsed("0x1.999999999999ap-4"), 0.1);
}

TEST(ParseDouble, UnderflowRoundsToZeroOrSubnormal) {
    EXPECT_EQ(parsed("4.9406564584124654e-324"), std::numeric_limits<double>::denorm_min());
    EXPECT_EQ(parsed("1e-400"), 0.0);
    EXPECT_TRUE(std::signbit(parsed("-1e-400")));
    EXPECT_EQ(parsed("0x1p-1080"), 0.0);
    // 3e-324 is above half the smallest subnormal: rounds up to it, not to zero.
    EXPECT_EQ(parsed("3e-324"), std::numeric_limits<double>::denorm_min());
}

TEST(ParseDouble, RejectsNonFinite) {
    for (const char* t : {"nan", "NaN", "-nan", "inf", "-Inf", "+INFINITY", "nan(0x1)", "0xinf"}) {
        EXPECT_NE(rejected(t).find("not a finite number"), std::string::npos) << t;
    }
}

TEST(ParseDouble, RejectsOverflow) {
    for (const char* t : {"1e400", "-1e309", "0x1p1024", "1.7976931348623159e308"}) {
        EXPECT_NE(rejected(t).find("outside the range"), std::string::npos) << t;
    }
}

TEST(ParseDouble, RejectsGarbage) {
    for (const char* t : {"", "abc", "1e", "1x", "--1", "+-1", "-+1", "0x-1", "0x", "0x+1", "1.2.3",
                          "0x1p", ".", "1,5", "1 ", " 1", "0b101", "1e+", "x1"}) {
        rejected(t);
    }
    EXPECT_NE(rejected("1.5abc").find("trailing characters 'abc'"), std::string::npos);
}

TEST(ParseQueryLine, BlankAndComments) {
    for (const char* line : {"", "   ", "\t", "# a comment", "   # indented comment", "\r"}) {
        EXPECT_EQ(parse_query_line(line).kind, ParsedLine::Kind::blank) << line;
    }
}

TEST(ParseQueryLine, Orient2d) {
    const ParsedLine p = parse_query_line("orient2d 0 0\t1 0 0x1p-1 1  # trailing comment\r");
    ASSERT_EQ(p.kind, ParsedLine::Kind::query) << p.error;
    EXPECT_EQ(p.query.predicate, Predicate::orient2d);
    EXPECT_EQ(p.query.points[0], (Point2{0, 0}));
    EXPECT_EQ(p.query.points[1], (Point2{1, 0}));
    EXPECT_EQ(p.query.points[2], (Point2{0.5, 1}));
}

TEST(ParseQueryLine, InCircleBoth) {
    for (Predicate pred : {Predicate::incircle, Predicate::incircle_cosine}) {
        const ParsedLine p =
            parse_query_line(std::string(predicate_name(pred)) + " 1 2 3 4 5 6 7 8#c");
        ASSERT_EQ(p.kind, ParsedLine::Kind::query) << p.error;
        EXPECT_EQ(p.query.predicate, pred);
        EXPECT_EQ(p.query.points[3], (Point2{7, 8}));
    }
}

TEST(ParseQueryLine, CompareDistanceTakesThreePoints) {
    const ParsedLine p = parse_query_line("compare_distance 1 2 3 4 5 6");
    ASSERT_EQ(p.kind, ParsedLine::Kind::query) << p.error;
    EXPECT_EQ(p.query.predicate, Predicate::compare_distance);
    EXPECT_EQ(p.query.points[2], (Point2{5, 6}));
    EXPECT_NE(parse_query_line("compare_distance 1 2 3 4 5 6 7 8").error.find("takes 6"),
              std::string::npos);
}

TEST(ParseQueryLine, SpacePredicatesTakeThreeCoordinatesPerPoint) {
    const ParsedLine o = parse_query_line("orient3d 1 2 3 4 5 6 7 8 9 0x1p-3 11 12 # c");
    ASSERT_EQ(o.kind, ParsedLine::Kind::query) << o.error;
    ASSERT_TRUE(o.query.space.has_value());
    EXPECT_EQ(*o.query.space, SpacePredicate::orient3d);
    EXPECT_EQ(o.query.points3[3], (Point3{0.125, 11, 12}));
    const ParsedLine i = parse_query_line("insphere 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15");
    ASSERT_EQ(i.kind, ParsedLine::Kind::query) << i.error;
    EXPECT_EQ(*i.query.space, SpacePredicate::insphere);
    EXPECT_EQ(i.query.points3[4], (Point3{13, 14, 15}));
    EXPECT_NE(parse_query_line("insphere 1 2 3 4 5 6 7 8 9 10 11 12")
                  .error.find("insphere takes 15 coordinates, got 12"),
              std::string::npos);
    EXPECT_NE(parse_query_line("orient3d 0 0 0 1 0 0 0 1 0 0 0 nan")
                  .error.find("coordinate 12: 'nan' is not a finite"),
              std::string::npos);
    // The kernels' answers through the parsed query: d below the plane of a CCW abc.
    const ParsedLine below = parse_query_line("orient3d 0 0 0 1 0 0 0 1 0 0 0 -1");
    EXPECT_EQ(evaluate(AdaptiveKernel{}, below.query), Sign::positive);
    EXPECT_EQ(evaluate(GmpExactKernel{}, below.query), Sign::positive);
}

TEST(ParseQueryLine, Errors) {
    const auto error_of = [](std::string_view line) {
        const ParsedLine p = parse_query_line(line);
        EXPECT_EQ(p.kind, ParsedLine::Kind::error) << line;
        return p.error;
    };
    EXPECT_NE(error_of("orient 0 0 1 0 0 1").find("unknown predicate 'orient'"), std::string::npos);
    EXPECT_NE(error_of("Orient2d 0 0 1 0 0 1").find("unknown predicate"), std::string::npos);
    EXPECT_NE(error_of("orient2d 0 0 1 0 0").find("takes 6 coordinates, got 5"), std::string::npos);
    EXPECT_NE(error_of("incircle 0 0 1 0 0 1").find("takes 8 coordinates, got 6"),
              std::string::npos);
    EXPECT_NE(error_of("incircle_cosine 0 0 1 0 0 1 1 1 1").find("got 9"), std::string::npos);
    EXPECT_NE(error_of("orient2d 0 0 1 nan 0 1").find("coordinate 4: 'nan' is not a finite"),
              std::string::npos);
    EXPECT_NE(error_of("orient2d 0 0 1 0 0 1e999").find("coordinate 6:"), std::string::npos);
    EXPECT_NE(error_of("orient2d 0,0 1,0 0,1").find("takes 6 coordinates, got 3"),
              std::string::npos);
}

TEST(ParseKernel, NamesRoundTrip) {
    for (const char* name : {"double", "long-double", "adaptive", "exact", "exact-cpp", "mpfr:53",
                             "mpfr:2", "mpfr:1048576"}) {
        std::string error;
        const std::optional<AnyKernel> k = parse_kernel(name, error);
        ASSERT_TRUE(k.has_value()) << name << ": " << error;
        EXPECT_EQ(std::visit([](const auto& kk) { return std::string(kk.name()); }, *k), name);
    }
}

TEST(ParseKernel, RejectsBadNames) {
    for (const char* name : {"", "Double", "mpfr", "mpfr:", "mpfr:1", "mpfr:0", "mpfr:-5",
                             "mpfr:53x", "mpfr:1048577", "mpfr:99999999999", "gmp"}) {
        std::string error;
        EXPECT_FALSE(parse_kernel(name, error).has_value()) << name;
        EXPECT_FALSE(error.empty()) << name;
    }
}

TEST(Evaluate, DispatchesEachPredicate) {
    const GmpExactKernel k;
    Query q;
    q.predicate = Predicate::orient2d;
    q.points = {Point2{0, 0}, Point2{1, 0}, Point2{0, 1}, Point2{0, 0}};
    EXPECT_EQ(evaluate(k, q), Sign::positive);
    q.predicate = Predicate::incircle;
    q.points[3] = Point2{0.25, 0.25};
    EXPECT_EQ(evaluate(k, q), Sign::positive);
    q.points[3] = Point2{1, 1};  // on the circle through (0,0), (1,0), (0,1)
    EXPECT_EQ(evaluate(k, q), Sign::zero);
    q.predicate = Predicate::incircle_cosine;
    q.points = {Point2{0, 0}, Point2{1, 0}, Point2{0.5, 1}, Point2{0.5, -0.1}};
    // c above ab, d below and inside the circle: orient2d * incircle = 1 * 1.
    EXPECT_EQ(evaluate(k, q), Sign::positive);
}

}  // namespace
}  // namespace exidel::cli
