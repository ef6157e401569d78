// Unit tests of the point readers and writers (exidel/io/points.hpp): every format, the
// error positions, and bit-exact round trips.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "exidel/io/points.hpp"

namespace exidel::io {
namespace {

using Points = std::vector<Point2>;

bool same_bits(const Points& a, const Points& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::bit_cast<std::uint64_t>(a[i].x) != std::bit_cast<std::uint64_t>(b[i].x) ||
            std::bit_cast<std::uint64_t>(a[i].y) != std::bit_cast<std::uint64_t>(b[i].y)) {
            return false;
        }
    }
    return true;
}

// The ReadError thrown by parsing `text`, or a test failure if none is.
ReadError error_of(std::string_view text, PointFormat f) {
    try {
        const Points p = parse_points(text, f);
        ADD_FAILURE() << "parsed " << p.size() << " points from: " << text;
    } catch (const ReadError& e) {
        return e;
    }
    return ReadError::at_line(0, "none");
}

void expect_error(std::string_view text, PointFormat f, std::size_t line, std::string_view reason) {
    const ReadError e = error_of(text, f);
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("line " + std::to_string(line) + ": ", 0), 0u)
        << e.what();
}

TEST(PointFormats, NamesAndExtensions) {
    EXPECT_EQ(point_format_from_path("a.json"), PointFormat::json);
    EXPECT_EQ(point_format_from_path("dir/a.node"), PointFormat::node);
    EXPECT_EQ(point_format_from_path("a.f64"), PointFormat::f64);
    EXPECT_EQ(point_format_from_path("a.csv"), PointFormat::xy);
    EXPECT_EQ(point_format_from_path("a.xy"), PointFormat::xy);
    EXPECT_EQ(point_format_from_path("points"), PointFormat::xy);
    for (PointFormat f :
         {PointFormat::xy, PointFormat::json, PointFormat::node, PointFormat::f64}) {
        EXPECT_EQ(point_format_from_name(to_string(f)), f);
    }
    EXPECT_FALSE(point_format_from_name("csv"));
}

TEST(ReadXy, SeparatorsCommentsHeaderAndLineEndings) {
    const Points p = parse_points(
        "# a comment line\n"
        "x,y\n"
        "1 2\n"
        "\n"
        "3,4   # trailing comment\n"
        "\t5 ,\t6\r\n"
        "0x1.8p1, -0.1\n"
        "7e-320 8",  // no final newline; a subnormal is fine
        PointFormat::xy);
    ASSERT_EQ(p.size(), 5u);
    EXPECT_EQ(p[0], (Point2{1, 2}));
    EXPECT_EQ(p[1], (Point2{3, 4}));
    EXPECT_EQ(p[2], (Point2{5, 6}));
    EXPECT_EQ(p[3], (Point2{3, -0.1}));
    EXPECT_EQ(p[4].x, 7e-320);
    EXPECT_EQ(p[4].y, 8);
}

TEST(ReadXy, EmptyInputIsNoPoints) {
    EXPECT_TRUE(parse_points("", PointFormat::xy).empty());
    EXPECT_TRUE(parse_points("\n\n# only comments\n  \n", PointFormat::xy).empty());
    EXPECT_TRUE(parse_points("lon lat\n", PointFormat::xy).empty());  // a header alone
}

TEST(ReadXy, ErrorsNameTheLine) {
    expect_error("0 0\n1 1\nfoo 2\n", PointFormat::xy, 3, "x: 'foo' is not a number");
    expect_error("0 0\n1 nan\n", PointFormat::xy, 2, "y: 'nan' is not a finite number");
    expect_error("0 0\n\n-inf 1\n", PointFormat::xy, 3, "not a finite number");
    expect_error("1e400 0\n", PointFormat::xy, 1, "outside the range");
    expect_error("0 0\n1 2 3\n", PointFormat::xy, 2, "expected 2 coordinates (x y), got 3");
    expect_error("# c\n\n7\n", PointFormat::xy, 3, "got 1");
    expect_error("0 0\n1,,2\n", PointFormat::xy, 2, "empty field");
    expect_error("1,2,\n", PointFormat::xy, 1, "empty field");
    expect_error(",1,2\n", PointFormat::xy, 1, "empty field");
    // Only the first line may be a header; "nan inf" is never one.
    expect_error("0 0\nx y\n", PointFormat::xy, 2, "not a number");
    expect_error("nan inf\n", PointFormat::xy, 1, "not a finite number");
    expect_error("x y\nx y\n", PointFormat::xy, 2, "not a number");
}

// The common "x y" line has a fast path (points.cpp, simple_xy); a comment on a line
// sends it down the general path. Lines of tricky tokens and separators, read with and
// without a comment: the same doubles (to the bit) or the same error.
TEST(ReadXy, FastPathReadsAsTheGeneralPath) {
    const std::vector<std::string> tokens{"0",
                                          "-0",
                                          "1",
                                          "-1.5",
                                          ".5",
                                          "-.5",
                                          "5.",
                                          "1e5",
                                          "1E-5",
                                          "-2.5e+3",
                                          "1e400",
                                          "1e-400",
                                          "4.9e-324",
                                          "0x1p3",
                                          "-0x1.8p1",
                                          "+1",
                                          "+.5",
                                          "nan",
                                          "-inf",
                                          "Infinity",
                                          "1.5e",
                                          ".",
                                          "-",
                                          "--1",
                                          "1_2",
                                          "12abc",
                                          "0.1000000000000000055511151231257827",
                                          "9007199254740993",
                                          "\"3\"",
                                          "",
                                          "1,5"};
    const std::vector<std::string> separators{" ", "\t", ",", " , ", ",  ", "  ", "", ",,"};
    std::mt19937_64 rng(49);
    const auto pick = [&](const std::vector<std::string>& v) { return v[rng() % v.size()]; };
    std::size_t read = 0, refused = 0;
    for (int i = 0; i < 20000; ++i) {
        const std::string line = (rng() % 4 == 0 ? " " : "") + pick(tokens) + pick(separators) +
                                 pick(tokens) + (rng() % 4 == 0 ? " \t" : "");
        std::optional<Points> fast, general;
        std::string fast_error, general_error;
        try {
            fast = parse_points("0 0\n" + line + "\n", PointFormat::xy);
        } catch (const ReadError& e) {
            fast_error = e.what();
        }
        try {
            general = parse_points("0 0\n" + line + " # comment\n", PointFormat::xy);
        } catch (const ReadError& e) {
            general_error = e.what();
        }
        ASSERT_EQ(fast.has_value(), general.has_value())
            << "'" << line << "': " << fast_error << " | " << general_error;
        if (!fast) {
            EXPECT_EQ(fast_error, general_error) << "'" << line << "'";
            ++refused;
            continue;
        }
        ++read;
        ASSERT_EQ(fast->size(), general->size()) << line;
        for (std::size_t k = 0; k < fast->size(); ++k) {
            EXPECT_EQ(std::bit_cast<std::uint64_t>((*fast)[k].x),
                      std::bit_cast<std::uint64_t>((*general)[k].x))
                << "'" << line << "'";
            EXPECT_EQ(std::bit_cast<std::uint64_t>((*fast)[k].y),
                      std::bit_cast<std::uint64_t>((*general)[k].y))
                << "'" << line << "'";
        }
    }
    EXPECT_GT(read, 1000u);  // both kinds of line were drawn many times
    EXPECT_GT(refused, 1000u);
}

TEST(ReadXy, ByteOrderMarkAndQuotedFields) {
    // A spreadsheet's CSV export: a UTF-8 byte order mark, quoted header and values.
    const Points p =
        parse_points("\xEF\xBB\xBF\"x\",\"y\"\r\n\"1.5\",2\r\n3, \"4\"\r\n", PointFormat::xy);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0], (Point2{1.5, 2}));
    EXPECT_EQ(p[1], (Point2{3, 4}));
    // The mark is skipped by the other text formats too; elsewhere it is an error.
    EXPECT_EQ(parse_points("\xEF\xBB\xBF[[1, 2]]", PointFormat::json).size(), 1u);
    EXPECT_EQ(parse_points("\xEF\xBB\xBF"
                           "1 2 0 0\n0 5 6\n",
                           PointFormat::node)
                  .size(),
              1u);
    expect_error(
        "1 2\n\xEF\xBB\xBF"
        "3 4\n",
        PointFormat::xy, 2, "not a number");
    expect_error("\"x\",\"y\n", PointFormat::xy, 1, "unterminated quoted field");
    expect_error("\"x\"z,y\n", PointFormat::xy, 1, "a quote inside a field is not supported");
}

Points with_columns(std::string_view text, std::string_view spec) {
    std::string error;
    const std::optional<Columns> c = parse_columns(spec, error);
    EXPECT_TRUE(c) << error;
    return parse_point_file(text, PointFormat::xy, ReadOptions{c}).points;
}

ReadError columns_error(std::string_view text, std::string_view spec) {
    try {
        with_columns(text, spec);
        ADD_FAILURE() << "no error for: " << text;
    } catch (const ReadError& e) {
        return e;
    }
    return ReadError::at_line(0, "none");
}

TEST(ReadXy, ColumnsByNumberAndByName) {
    const std::string csv =
        "id,\"name, with comma\",lon,lat\n"
        "1,\"Paris, FR\",2.35,48.85\n"
        "2,,-0.12,51.5\n";  // an empty field that is not picked is fine
    for (const std::string_view spec : {"3,4", "lon,lat"}) {
        const Points p = with_columns(csv, spec);
        ASSERT_EQ(p.size(), 2u) << spec;
        EXPECT_EQ(p[0], (Point2{2.35, 48.85}));
        EXPECT_EQ(p[1], (Point2{-0.12, 51.5}));
    }
    EXPECT_EQ(with_columns(csv, "lat,lon")[0], (Point2{48.85, 2.35}));  // any order
    // Without a header, by number: every line is data.
    EXPECT_EQ(with_columns("7 1 2\n8 3 4\n", "2,3"), (Points{{1, 2}, {3, 4}}));

    EXPECT_NE(std::string(columns_error(csv, "lon,height").what())
                  .find("line 1: no column named 'height' in the first line ('id', "),
              std::string::npos);
    EXPECT_EQ(columns_error("1 2 3\n4 5 6\n", "2,4").line(), 1u);        // no 4th field
    EXPECT_EQ(columns_error("1 2 3\n4 5\n", "1,2").line(), 2u);          // width changes
    EXPECT_EQ(columns_error("a,b,a\n1,2,3\n", "a,b").line(), 1u);        // ambiguous name
    EXPECT_EQ(columns_error("a,b,c\n1,2,3\n1,,3\n", "1,2").line(), 3u);  // picked and empty

    std::string error;
    for (const std::string_view bad : {"", "1", "1,2,3,4", ",2", "0,1", "1x,2", "1,2,"}) {
        EXPECT_FALSE(parse_columns(bad, error)) << bad;
        EXPECT_FALSE(error.empty());
    }
    EXPECT_THROW(parse_point_file("[]", PointFormat::json, ReadOptions{Columns{"1", "2"}}),
                 std::invalid_argument);
    // Without columns, a wider line says how to pick two.
    expect_error("1,2,3\n", PointFormat::xy, 1, "pick two with --columns X,Y");
}

TEST(ReadXy, ThreadsGiveTheSamePointsAndTheSameErrorLine) {
    // About 3 MB: three parts of at least 1 MiB each, cut at line ends.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1e6, 1e6);
    std::ostringstream text;
    text.precision(17);
    text << "x,y\n";
    for (int i = 0; i < 90000; ++i) {
        text << u(rng) << (i % 3 ? " " : ", ") << u(rng) << (i % 1000 == 0 ? "  # c\n\n" : "\n");
    }
    const std::string data = text.str();
    ASSERT_GT(data.size(), 3u << 20);
    const Points one = parse_point_file(data, PointFormat::xy, ReadOptions{{}, 1}).points;
    ASSERT_EQ(one.size(), 90000u);
    for (const unsigned threads : {2u, 3u, 8u}) {
        EXPECT_TRUE(same_bits(
            parse_point_file(data, PointFormat::xy, ReadOptions{{}, threads}).points, one))
            << threads;
    }
    // A bad line late in the input (in the last part) and a second one after it: the
    // error is the first, at its line in the whole input, whatever the thread count.
    std::string bad = data;
    std::size_t line = 0, at = 0;
    for (std::size_t i = 0; i < bad.size() && line < 79000; ++i) {
        if (bad[i] == '\n' && ++line == 79000) at = i + 1;
    }
    bad.insert(at, "1 2 3\n");
    bad += "oops\n";
    for (const unsigned threads : {1u, 2u, 3u}) {
        try {
            parse_point_file(bad, PointFormat::xy, ReadOptions{{}, threads});
            ADD_FAILURE() << "no error";
        } catch (const ReadError& e) {
            EXPECT_EQ(e.line(), 79001u) << threads << ": " << e.what();
        }
    }
}

TEST(ReadFile, SaysWhyAFileCannotBeRead) {
    const auto message = [](const std::string& path) {
        try {
            const FileBytes bytes(path);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("/nonexistent/points.xy"),
              "cannot read '/nonexistent/points.xy': No such file or directory");
    EXPECT_EQ(message("/"), "cannot read '/': Is a directory");
    // /proc files report size 0 but have contents: the size is only a hint.
    EXPECT_FALSE(FileBytes("/proc/self/status").view().empty());
    // A regular file: the same bytes as written.
    const std::string path = ::testing::TempDir() + "exidel-filebytes.xy";
    const std::string text = "1 2\n3 4\n";
    std::ofstream(path, std::ios::binary) << text;
    EXPECT_EQ(FileBytes(path).view(), text);
    std::ofstream(path, std::ios::binary | std::ios::trunc).close();
    EXPECT_TRUE(FileBytes(path).view().empty());
}

// Another process truncating and rewriting the input while it is read: every read gives
// a prefix of the file's only content or says that the input changed, and never crashes.
// (When the file was mapped, a truncation made the reader's next access to a lost page
// raise SIGBUS, and a rewrite could change the bytes between the parser's passes.) The
// writer only ever truncates the file to half and writes the second half back, so any
// bytes a read sees are the content's bytes at their places.
TEST(ReadFile, AFileChangedWhileReadIsACopyOrSaidNeverACrash) {
    const std::string path = ::testing::TempDir() + "exidel-filebytes-changing.xy";
    std::string content;
    for (int i = 0; content.size() < (8u << 20); ++i) content += std::to_string(i) + " 0.5\n";
    std::ofstream(path, std::ios::binary) << content;
    const std::size_t half = content.size() / 2;
    std::atomic<bool> stop{false};
    std::thread writer([&] {
        const int fd = ::open(path.c_str(), O_WRONLY);
        while (!stop.load()) {
            if (::ftruncate(fd, static_cast<off_t>(half)) != 0) break;
            if (::pwrite(fd, content.data() + half, content.size() - half,
                         static_cast<off_t>(half)) < 0) {
                break;
            }
        }
        ::close(fd);
    });
    int copies = 0, said = 0;
    for (int i = 0; i < 200; ++i) {
        try {
            const FileBytes bytes(path);
            EXPECT_EQ(bytes.view(), std::string_view(content).substr(0, bytes.view().size()));
            ++copies;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("changed while it was read"), std::string::npos)
                << e.what();
            ++said;
        }
    }
    stop = true;
    writer.join();
    EXPECT_EQ(copies + said, 200);
    std::printf("200 reads of a changing file: %d copies, %d said it changed\n", copies, said);
}

TEST(ReadJson, ArrayOfPairs) {
    const Points p = parse_points(" [ [0, 0],\n[1.5, -2e-3] ,[ -0 ,1E2]]\n\n", PointFormat::json);
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p[1], (Point2{1.5, -2e-3}));
    EXPECT_EQ(p[2], (Point2{0, 100}));
    EXPECT_TRUE(std::signbit(p[2].x));
    EXPECT_TRUE(parse_points("", PointFormat::json).empty());
    EXPECT_TRUE(parse_points(" \n ", PointFormat::json).empty());
    EXPECT_TRUE(parse_points("[]", PointFormat::json).empty());
    EXPECT_TRUE(parse_points("[\n]\n", PointFormat::json).empty());
}

TEST(ReadJson, ErrorsNameTheLine) {
    expect_error("[[0, 0],\n [1, 2, 3]]", PointFormat::json, 2, "third coordinate");
    expect_error("[[0, 0],\n\n [1]]", PointFormat::json, 3, "y is missing");
    expect_error("[[0, 0],\n [1, NaN]]", PointFormat::json, 2, "not a finite number");
    expect_error("[[0, 0],\n [Infinity, 1]]", PointFormat::json, 2, "not a finite number");
    expect_error("[[0, 1e999]]", PointFormat::json, 1, "outside the range");
    expect_error("[[0x1p3, 0]]", PointFormat::json, 1, "not a JSON number");
    expect_error("[[01, 0]]", PointFormat::json, 1, "not a JSON number");
    expect_error("[[+1, 0]]", PointFormat::json, 1, "expected a number");
    expect_error("[[1., 0]]", PointFormat::json, 1, "digits must follow '.'");
    expect_error("[[0, 0]]\n[[1, 1]]", PointFormat::json, 2, "after the closing ']'");
    expect_error("[[0, 0],\n [1, 1]", PointFormat::json, 2, "the end of the input");
    expect_error("[[0, 0],\n [1, 1],\n]", PointFormat::json, 3, "expected '['");
    expect_error("{\"points\": []}", PointFormat::json, 1, "expected '['");
    expect_error("[\n[0, 0]\n[1, 1]]", PointFormat::json, 3, "or ',' after a point");
}

TEST(ReadNode, ZeroAndOneBasedWithAttributesAndMarkers) {
    const Points zero =
        parse_points("# Triangle node file\n3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n", PointFormat::node);
    const Points one =
        parse_points("3 2 1 1\n1 0 0 7.5 1\n2 1 0 -3 0\n\n3 0 1 0x1p3 1 # c\n", PointFormat::node);
    const Points defaults = parse_points("3\n0 0 0\n1 1 0\n2 0 1\n", PointFormat::node);
    const Points expected{{0, 0}, {1, 0}, {0, 1}};
    EXPECT_EQ(zero, expected);
    EXPECT_EQ(one, expected);
    EXPECT_EQ(defaults, expected);
    EXPECT_TRUE(parse_points("", PointFormat::node).empty());
    EXPECT_TRUE(parse_points("0 2 0 0\n", PointFormat::node).empty());
    // The numbering base is kept, so that an .ele written for the file counts the same way,
    // and the writer numbers from it.
    EXPECT_EQ(parse_point_file("3\n1 0 0\n2 1 0\n3 0 1\n", PointFormat::node).index_base, 1u);
    EXPECT_EQ(parse_point_file("3\n0 0 0\n1 1 0\n2 0 1\n", PointFormat::node).index_base, 0u);
    std::ostringstream out;
    write_points(out, expected, PointFormat::node, 1);
    EXPECT_EQ(out.str(), "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n");
}

TEST(ReadNode, ErrorsNameTheLine) {
    expect_error("3 3 0 0\n", PointFormat::node, 1, "dimension 3, expected 2");
    expect_error("3 2 0 2\n", PointFormat::node, 1, "markers 2 is outside [0, 1]");
    expect_error("-1 2 0 0\n", PointFormat::node, 1, "number of vertices -1");
    expect_error("2 2 0 0 9\n", PointFormat::node, 1, "got 5 fields");
    expect_error("3 2 0 0\n0 0 0\n1 1 0\n", PointFormat::node, 3, "truncated");
    expect_error("2 2 0 0\n0 0 0\n1 1 0\n2 0 1\n", PointFormat::node, 4, "more vertex lines");
    expect_error("2 2 0 0\n0 0 0\n2 1 0\n", PointFormat::node, 3, "vertex index 2, expected 1");
    expect_error("2 2 0 0\n5 0 0\n", PointFormat::node, 2, "first vertex index");
    expect_error("2 2 1 0\n0 0 0\n1 1 0\n", PointFormat::node, 2, "expected 4 fields");
    expect_error("1 2 0 1\n0 0 0 x\n", PointFormat::node, 2, "boundary marker");
    expect_error("1 2 1 0\n0 0 0 nan\n", PointFormat::node, 2, "attribute");
    expect_error("1 2 0 0\n0 0 inf\n", PointFormat::node, 2, "y: 'inf' is not a finite number");
}

std::string f64_bytes(const std::vector<double>& values) {
    std::string s(values.size() * 8, '\0');
    for (std::size_t i = 0; i < values.size(); ++i) {
        const auto bits = std::bit_cast<std::uint64_t>(values[i]);
        for (int b = 0; b < 8; ++b) s[8 * i + b] = static_cast<char>((bits >> (8 * b)) & 0xff);
    }
    return s;
}

TEST(ReadF64, LittleEndianPairs) {
    const Points p = parse_points(f64_bytes({1, 2, -0.1, 5e-324}), PointFormat::f64);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0], (Point2{1, 2}));
    EXPECT_EQ(p[1], (Point2{-0.1, 5e-324}));
    EXPECT_TRUE(parse_points("", PointFormat::f64).empty());
}

TEST(ReadF64, ErrorsNameTheByteOffset) {
    std::string truncated = f64_bytes({1, 2, 3});
    ReadError e = error_of(truncated, PointFormat::f64);
    EXPECT_EQ(e.byte_offset(), 16u);
    EXPECT_EQ(e.line(), 0u);
    EXPECT_EQ(std::string(e.what()).rfind("byte offset 16: truncated", 0), 0u) << e.what();

    e = error_of(f64_bytes({1, 2, 3, std::numeric_limits<double>::quiet_NaN()}), PointFormat::f64);
    EXPECT_EQ(e.byte_offset(), 24u);
    EXPECT_NE(std::string(e.what()).find("y of point 1 is NaN"), std::string::npos) << e.what();

    e = error_of(f64_bytes({-std::numeric_limits<double>::infinity(), 0}), PointFormat::f64);
    EXPECT_EQ(e.byte_offset(), 0u);
    EXPECT_NE(std::string(e.what()).find("x of point 0 is infinite"), std::string::npos);
}

// Doubles that a careless writer or reader would change: negative zero, subnormals, the
// extremes, values with 17 significant digits, and uniform random ones.
Points tricky_points() {
    Points p{{-0.0, 0.0},
             {5e-324, -2.2250738585072014e-308},
             {1.7976931348623157e308, -1.7976931348623157e308},
             {0.1, 17.300000000000001},
             {24.00000000000005, 24.0000000000000517765},
             {std::nextafter(0.5, 1.0), 1e22}};
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1e3, 1e3);
    for (int i = 0; i < 200; ++i) p.push_back({u(rng), u(rng)});
    return p;
}

TEST(WritePoints, RoundTripIsBitExactInEveryFormat) {
    const Points p = tricky_points();
    for (PointFormat f :
         {PointFormat::xy, PointFormat::json, PointFormat::node, PointFormat::f64}) {
        std::ostringstream out;
        write_points(out, p, f);
        std::istringstream in(out.str());
        EXPECT_TRUE(same_bits(read_points(in, f), p)) << to_string(f);
        std::ostringstream empty;
        write_points(empty, {}, f);
        EXPECT_TRUE(parse_points(empty.str(), f).empty()) << to_string(f);
    }
}

TEST(WritePoints, TextFormatsRefuseNonFinite) {
    const Points p{{0, std::numeric_limits<double>::infinity()}};
    std::ostringstream out;
    EXPECT_THROW(write_points(out, p, PointFormat::xy), std::invalid_argument);
}

}  // namespace
}  // namespace exidel::io
