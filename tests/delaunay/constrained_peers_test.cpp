// The constrained Delaunay triangulation (exidel/delaunay/constrained.hpp) on the inputs of
// other constrained-triangulation libraries' bug reports: inputs that made that library
// hang, crash, assert or give a wrong result, transcribed from the report (or from the
// regression test the report led to, where named) with the report's decimal literals, as
// doubles. Each is run with the adaptive and the GMP exact kernel: both succeed, both are
// certified exactly (certify_constrained), both give the same arrays; where no segments
// cross, or where rounding the exact arrangement cascades nowhere, the vertices and
// constraint pieces are CGAL's (Constrained_Delaunay_triangulation_2 over Epeck with
// Exact_intersections_tag); where the report states an output that can be checked, it is
// checked. The double kernel must return (a result or a typed failure) and never crash or
// hang. exidel always resolves crossing segments (a vertex at the rounded crossing), so the
// peers' "resolve intersections" modes need no counterpart here.
#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "constrained_support.hpp"
#include "exidel/delaunay/constrained.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/floating.hpp"

namespace exidel::test {
namespace {

using delaunay::certify_constrained;
using delaunay::ConstrainedResult;
using delaunay::ConstrainedTriangulation;
using delaunay::Segment;

struct Input {
    std::vector<Point2> points;
    std::vector<Segment> segments;
};

/// artem-ogre/CDT's text format: "n m", n lines "x y", m lines "a b" (0-based indices).
Input parse_cdt_text(const std::string& text) {
    std::istringstream in(text);
    std::size_t n = 0, m = 0;
    in >> n >> m;
    Input input;
    for (std::size_t i = 0; i < n; ++i) {
        Point2 p{};
        in >> p.x >> p.y;
        input.points.push_back(p);
    }
    for (std::size_t i = 0; i < m; ++i) {
        Segment s{};
        in >> s.a >> s.b;
        input.segments.push_back(s);
    }
    EXPECT_FALSE(in.fail()) << "malformed input text";
    return input;
}

/// Points given as a polyline or polygon: segments i -> i + 1, and back to 0 if closed.
std::vector<Segment> path_segments(std::uint32_t first, std::uint32_t count, bool closed) {
    std::vector<Segment> segments;
    for (std::uint32_t i = 0; i + 1 < count; ++i) segments.push_back({first + i, first + i + 1});
    if (closed && count > 2) segments.push_back({first + count - 1, first});
    return segments;
}

/// Segments given as pairs of points (spade's tests insert both ends of every edge):
/// points 2s and 2s + 1 are the ends of segment s; repeated points stay repeated.
Input from_point_pairs(const std::vector<std::pair<Point2, Point2>>& pairs) {
    Input input;
    for (const auto& [a, b] : pairs) {
        const auto k = static_cast<std::uint32_t>(input.points.size());
        input.points.push_back(a);
        input.points.push_back(b);
        input.segments.push_back({k, k + 1});
    }
    return input;
}

std::string describe(const ConstrainedResult& r) {
    if (!r.ok())
        return std::string(delaunay::to_string(r.failure->kind)) + ": " + r.failure->message;
    return "ok, " + std::to_string(r.cdt.added_count()) + " added, " +
           std::to_string(r.cdt.triangulation.triangle_count()) + " triangles";
}

/// The checks every report gets (see the top of the file); returns the adaptive kernel's
/// triangulation for the report's own checks. Outcomes are recorded as test properties
/// (--gtest_output=xml shows them).
ConstrainedTriangulation replay(const Input& in) {
    const ConstrainedResult adaptive = run(in.points, in.segments, AdaptiveKernel{});
    const ConstrainedResult exact = run(in.points, in.segments, GmpExactKernel{});
    const ConstrainedResult floating = run(in.points, in.segments, DoubleKernel{});
    ::testing::Test::RecordProperty("adaptive", describe(adaptive));
    ::testing::Test::RecordProperty("exact", describe(exact));
    ::testing::Test::RecordProperty("double", describe(floating));
    // The double kernel: a result with a chain per segment, or a typed failure.
    if (floating.ok()) {
        EXPECT_EQ(floating.cdt.chain_offsets.size(), in.segments.size() + 1);
        ::testing::Test::RecordProperty(
            "double_certified",
            certify_constrained(in.points, in.segments, floating.cdt).ok() ? "yes" : "no");
    } else {
        EXPECT_FALSE(floating.failure->message.empty());
    }
    EXPECT_TRUE(adaptive.ok()) << describe(adaptive);
    EXPECT_TRUE(exact.ok()) << describe(exact);
    if (!adaptive.ok() || !exact.ok()) return {};
    const delaunay::Certificate ca = certify_constrained(in.points, in.segments, adaptive.cdt);
    EXPECT_TRUE(ca.ok()) << ca.summary();
    const delaunay::Certificate ce = certify_constrained(in.points, in.segments, exact.cdt);
    EXPECT_TRUE(ce.ok()) << ce.summary();
    EXPECT_EQ(adaptive.cdt.points, exact.cdt.points);
    EXPECT_EQ(adaptive.cdt.triangulation.triangles, exact.cdt.triangulation.triangles);
    EXPECT_EQ(adaptive.cdt.constraints, exact.cdt.constraints);
    EXPECT_EQ(adaptive.cdt.chain_vertices, exact.cdt.chain_vertices);
    // CGAL's vertices and pieces, wherever nothing cascades. added_count() == 0 is not
    // enough: a crossing that rounds onto a vertex adds none.
    const Shape cgal = cgal_shape(in.points, in.segments);
    const bool plain =
        rounding_keeps_an_arrangement(cgal) && no_cascade_in(adaptive.cdt, in.points, in.segments);
    ::testing::Test::RecordProperty("compared_with_cgal", plain ? "yes" : "no (cascade)");
    if (plain) {
        const Shape ours = our_shape(adaptive.cdt);
        EXPECT_EQ(ours.vertices, cgal.vertices);
        EXPECT_EQ(ours.pieces, cgal.pieces);
    }
    return adaptive.cdt;
}

std::vector<std::uint32_t> chain_of(const ConstrainedTriangulation& cdt, std::size_t s) {
    const auto c = cdt.chain(s);
    return {c.begin(), c.end()};
}

// ---- kninnug/Constrainautor (JavaScript, on top of Delaunator) ------------------------------

// https://github.com/kninnug/Constrainautor/issues/2 (input as the repository's
// tests/issue2.json keeps it). Constrainautor looped forever: a sliver triangle along the
// hull made the walk along a constraint step onto an outer half-edge. Hard: an integer grid
// of 171 points inside a closed polygon of 65 points that run nearly collinear along the
// convex hull (many thin hull triangles, constraints on and near the hull).
TEST(ConstrainedPeerReports, ConstrainautorIssue2GridInsidePolygon) {
    Input in;
    for (int y = 1; y <= 14; ++y) {
        const int lo = y <= 8 ? 2 : 1;
        const int hi = y <= 11 ? 13 : 12;
        for (int x = lo; x <= hi; ++x) in.points.push_back({double(x), double(y)});
    }
    ASSERT_EQ(in.points.size(), 171u);
    const std::vector<Point2> outline{
        {0, 14.404910396560176},
        {0.1097833356951295, 13.512342151010488},
        {0.219566671390259, 12.6197739054608},
        {0.3293500070853885, 11.727205659911116},
        {0.439133342780518, 10.834637414361424},
        {0.5489166784756471, 9.942069168811738},
        {0.6587000141707766, 9.04950092326205},
        {0.768483349865906, 8.156932677712362},
        {0.8782666855610356, 7.264364432162673},
        {0.988050021256165, 6.371796186612986},
        {1.0978333569512946, 5.479227941063298},
        {1.2076166926464236, 4.58665969551361},
        {1.3174000283415532, 3.6940914499639224},
        {1.4271833640366824, 2.8015232044142344},
        {1.536966699731812, 1.908954958864547},
        {1.6467500354269418, 1.0163867133148592},
        {1.7565333711220712, 0.12381846776517148},
        {2.625357004835959, 0.18948424425307334},
        {3.49774548578131, 0.17614930575222743},
        {4.377480950347606, 0},
        {5.03667324191489, 0.03551984647853645},
        {5.695865533482174, 0.0710396929570729},
        {6.2976567830833465, 0.22587193892879634},
        {6.899448032684518, 0.38070418490052144},
        {7.003061369329261, 0.37532483863500393},
        {7.5514736580060084, 0.3124430512698645},
        {8.099885946682761, 0.2495612639047251},
        {8.717896070125907, 0.3415446219466246},
        {9.33590619356905, 0.4335279799885241},
        {10.26668585466961, 0.4655189291422352},
        {11.197465515770173, 0.4975098782959462},
        {11.844773441110322, 0.4704867438747797},
        {12.492081366450472, 0.44346360945361146},
        {13.099038695146895, 0.5505512714034877},
        {13.705996023843316, 0.6576389333533622},
        {14, 0.7212017967478266},
        {13.9812640368062, 1.5897138741882504},
        {13.9625280736124, 2.4582259516286733},
        {13.943792110418599, 3.3267380290690935},
        {13.9250561472248, 4.195250106509518},
        {13.906320184030996, 5.0637621839499385},
        {13.887584220837196, 5.932274261390362},
        {13.868848257643396, 6.800786338830786},
        {13.850112294449596, 7.669298416271207},
        {13.831376331255797, 8.53781049371163},
        {13.812640368061993, 9.406322571152053},
        {13.607759847190183, 10.205419346701756},
        {13.402879326318374, 11.004516122251466},
        {13.19799880544656, 11.803612897801173},
        {12.99311828457475, 12.60270967335088},
        {12.788237763702941, 13.401806448900587},
        {12.58335724283113, 14.200903224450293},
        {12.378476721959318, 15},
        {11.426286204885525, 14.954223876658476},
        {10.474095687811731, 14.908447753316947},
        {9.521905170737938, 14.862671629975427},
        {8.569714653664144, 14.8168955066339},
        {7.617524136590351, 14.771119383292376},
        {6.665333619516556, 14.725343259950849},
        {5.7131431024427615, 14.679567136609325},
        {4.760952585368969, 14.6337910132678},
        {3.808762068295175, 14.588014889926276},
        {2.8565715512213803, 14.542238766584749},
        {1.9043810341475864, 14.496462643243225},
        {0.9521905170737933, 14.450686519901703},
    };
    in.points.insert(in.points.end(), outline.begin(), outline.end());
    in.segments = path_segments(171, 65, true);  // [171, 172], ..., [234, 235], [235, 171]
    const ConstrainedTriangulation cdt = replay(in);
    // The report's polygon does not cross itself: no crossing points.
    EXPECT_EQ(cdt.added_count(), 0u);
}

// https://github.com/kninnug/Constrainautor/issues/4. Constrainautor threw "Infinite loop: no
// further intersect after non-convex" on constrainOne(7, 9): the Delaunay property was
// restored only after all constraints, not after each. Hard: six constraints that share ends
// and run through thin, non-convex pseudo-polygons of a small integer point set.
TEST(ConstrainedPeerReports, ConstrainautorIssue4NonConvexPseudoPolygon) {
    Input in{{{544, 480},
              {512, 192},
              {544, 160},
              {512, 384},
              {512, 224},
              {544, 320},
              {704, 128},
              {576, 352},
              {672, 352},
              {576, 128},
              {608, 384},
              {672, 96},
              {640, 96},
              {608, 160},
              {672, 160},
              {608, 288}},
             {{1, 2}, {4, 5}, {5, 0}, {6, 8}, {8, 7}, {7, 9}}};
    replay(in);
}

// https://github.com/kninnug/Constrainautor/issues/15. Constrainautor looped forever (still
// open when stored); it went away when the coordinates were scaled up. Hard: points 2 and 5
// are 1e-17 apart across the x-axis, the constraints 0-5 and 5-2 form a hair-thin wedge with
// point 1 on the x-axis just beyond.
TEST(ConstrainedPeerReports, ConstrainautorIssue15NearDegenerateEdge) {
    Input in{{{0, 0},
              {0.05626429153399996, 0},
              {0.024093852080076722, 4.80267923973791e-18},
              {0.01379050745122589, 0.1463775332929564},
              {0.05177587092034522, 0.015468457826306506},
              {0.024093852080076705, -5.204170427930421e-18}},
             {{0, 5}, {5, 2}}};
    const ConstrainedTriangulation cdt = replay(in);
    EXPECT_EQ(cdt.added_count(), 0u);
}

// ---- Stoeoef/spade (Rust) -------------------------------------------------------------------

// https://github.com/Stoeoef/spade/issues/98 (f32 and f64; the input as spade's regression
// test infinite_loop_bug in src/cdt.rs keeps it). Spade looped forever in
// locate_with_hint_fixed_core when inserting the point `start` after ten constraints that
// pass can_add_constraint. Hard: float32 values, a repeated end point, long constraints
// nearly parallel to each other; the last point is inserted after the constraints (here it is
// simply the last input point).
TEST(ConstrainedPeerReports, SpadeIssue98LocateLoopsAfterConstraints) {
    Input in = from_point_pairs({
        {{-20.926544189453125, 16.53529167175293}, {-27.772645950317383, 4.197676658630371}},
        {{-20.03745460510254, 12.93730354309082}, {-20.930097579956055, 11.93786907196045}},
        {{-15.576859474182129, 8.772907257080078}, {-22.373262405395508, 12.348699569702148}},
        {{-10.038422584533691, 5.663522243499756}, {-16.382625579833984, 9.09498119354248}},
        {{0.0, 0.0}, {-13.11422061920166, 7.30709171295166}},
        {{-19.230497360229492, -3.7645812034606934}, {-7.411926746368408, 3.486957311630249}},
        {{-25.072885513305664, -9.239323616027832}, {-19.462360382080078, -1.621320366859436}},
        {{-32.41080856323242, -13.72575855255127}, {-22.58626365661621, -2.076631784439087}},
        {{-32.41080856323242, -13.72575855255127}, {-25.57504653930664, -4.952820301055908}},
        {{-33.08932113647461, 0.31093916296958923}, {-25.955543518066406, 0.18878456950187683}},
    });
    in.points.push_back({-21.296192169189453, 9.872323036193848});  // `start`
    const ConstrainedTriangulation cdt = replay(in);
    // The report: the constraints do not cross (spade's can_add_constraint accepts each).
    EXPECT_EQ(cdt.added_count(), 0u);
}

// https://github.com/Stoeoef/spade/issues/107 (found by fuzzing; the input as spade's
// regression test infinite_loop_2 in src/cdt.rs reduces it). After add_constraint_and_split
// of three crossing segments, inserting a point panicked with "Failed to locate position.
// This is a bug in spade." Hard: the rounded crossing points leave the split pieces slightly
// bent, and the point is then located among them.
TEST(ConstrainedPeerReports, SpadeIssue107LocateAfterSplitPanics) {
    Input in = from_point_pairs({
        {{0.9296344883099084, 0.03071359966930065}, {0.26031306872107085, 0.34491289915959455}},
        {{0.7384289920396423, 0.4981747664368982}, {0.06543525273452533, 0.34139896206401854}},
        {{0.9535295221136963, 0.9114305148801416}, {0.8306091165247367, 0.08959389670590667}},
    });
    in.points.push_back({0.5138795569454557, 0.3186272217036502});
    replay(in);
}

// https://github.com/Stoeoef/spade/issues/111 (f64; spade's regression test
// edge_intersection_precision_test_2). Spade 2.11 failed an internal assertion in
// add_constraint_and_split. Hard: float32 values as doubles, a segment crossing two others
// near where they meet, three segments nearly along the line y = x + 0.896.
TEST(ConstrainedPeerReports, SpadeIssue111SplitAssertion) {
    const Input in = from_point_pairs({
        {{18.69314193725586, 19.589109420776367}, {18.69314193725586, 20.40362548828125}},
        {{19.507659912109375, 20.40362548828125}, {17.878625869750977, 18.774595260620117}},
        {{20.322175979614258, 21.218143463134766}, {15.435077667236328, 16.331045150756836}},
    });
    replay(in);
}

// https://github.com/Stoeoef/spade/issues/113 (f32; the two segments to which spade's
// regression test edge_intersection_precision_test_3 reduces the report's polygon). Spade
// panicked in add_constraint_and_split: in f32 the crossing rounds onto an existing vertex.
// The float32 decimal literals are used as doubles here, so that coincidence need not recur.
TEST(ConstrainedPeerReports, SpadeIssue113CrossingOnAVertex) {
    const Input in = from_point_pairs({
        {{-11.673287, -28.37192}, {-16.214716, -43.81278}},
        {{7.4022045, -51.355137}, {-13.92232, -36.01863}},
    });
    replay(in);
}

// https://github.com/Stoeoef/spade/issues/116 (f64, spade 2.12.1). Another failure of
// add_constraint_and_split (fixed by a new split algorithm, PR #128). Hard: float32 values
// as doubles, two segments nearly collinear with a third (the line y = x + 0.896), one of
// them ending at a point where a vertical segment also ends.
TEST(ConstrainedPeerReports, SpadeIssue116SplitEdgeCase) {
    const Input in = from_point_pairs({
        {{15.435077667236328, 16.331045150756836}, {20.322175979614258, 21.218143463134766}},
        {{18.69314193725586, 19.589109420776367}, {19.507659912109375, 20.40362548828125}},
        {{19.507659912109375, 21.218143463134766}, {19.507659912109375, 20.40362548828125}},
        {{17.878625869750977, 18.774595260620117}, {19.507659912109375, 20.40362548828125}},
    });
    replay(in);
}

// ---- artem-ogre/CDT (C++) -------------------------------------------------------------------

// https://github.com/artem-ogre/CDT/issues/139 (input CDT/tests/inputs/HangingIntersection.txt).
// CDT crashed resolving the crossing of two constraints when the pseudo-polygon beside the
// constraint has a hanging edge (a vertex reached by one edge only). CDT needs
// IntersectingConstraintEdges::TryResolve for this; exidel always resolves crossings.
TEST(ConstrainedPeerReports, CdtIssue139HangingIntersection) {
    const Input in = parse_cdt_text(R"(7 2
725.0 415.0
855.0 390.0
945.0 455.0
1100.0 373.0
1215.0 410.0
1250.0 510.0
943.0 540.0
3 5
0 4)");
    const ConstrainedTriangulation cdt = replay(in);
    EXPECT_EQ(cdt.added_count(), 1u);
}

// https://github.com/artem-ogre/CDT/issues/142 (the 9-point polygon of the maintainer's
// corrected input in the thread, reduced from poly2tri's testbed debug2.dat). CDT failed the
// assertion outerTri != iT in Triangulation.hpp. Hard: a thin polygon whose vertices come in
// nearly collinear runs. The reporter: "No intersections. No dots on the edges."
TEST(ConstrainedPeerReports, CdtIssue142AssertOnThinPolygon) {
    const Input in = parse_cdt_text(R"(9 9
2.7145555 -1.5168651
2.5013921 -1.39569
3.0311139 -1.6827598
2.7610707 -1.5269606
2.7745042 -1.5207595
2.8049774 -1.4492451
4.2982483 -2.210517
2.8477705 -1.6077808
2.3252072 -1.3108287
0   1
1   2
2   3
3   4
4   5
5   6
6   7
7   8
8   0)");
    const ConstrainedTriangulation cdt = replay(in);
    // As the reporter states: no crossings and no vertex on an edge, so every segment is one
    // piece.
    EXPECT_EQ(cdt.added_count(), 0u);
    for (std::size_t s = 0; s < in.segments.size(); ++s)
        EXPECT_EQ(cdt.chain(s).size(), 2u) << "segment " << s;
}

// https://github.com/artem-ogre/CDT/pull/149 "#148 Fix bug when resolving intersections"
// (regression input CDT/tests/inputs/issue-148-crossing-edges.txt). CDT mishandled resolving
// the crossing of two constraints (TryResolve mode; exidel always resolves crossings). Hard:
// two points lie inside the quadrilateral of the crossing constraints, close to one of them.
TEST(ConstrainedPeerReports, CdtIssue148CrossingEdges) {
    const Input in = parse_cdt_text(R"(6 2
0 0.2
1 0
1 1
0 1
0.5 0.2
0.8 0.5
0 2
1 3)");
    const ConstrainedTriangulation cdt = replay(in);
    EXPECT_EQ(cdt.added_count(), 1u);
    EXPECT_EQ(cdt.constraints.size(), 4u);
}

// https://github.com/artem-ogre/CDT/issues/211 (the reporter's polygon from the gist it links,
// as CDT keeps it in CDT/tests/inputs/issue-211.txt). CDT 1.4.4 threw "Could not find vertex
// triangle intersected by an edge" with the default minDistToConstraintEdge = 0 (a rounded
// crossing of nearly parallel constraints fell outside the triangles beside the split edge;
// fixed by PR #216, which throws InvalidEdgeSplitVertex instead). Hard: 97 points and 98
// constraints with nearly parallel, nearly touching edges, points 1e-32 and 1e-6 off axes.
TEST(ConstrainedPeerReports, CdtIssue211PolygonCrash) {
    const Input in = parse_cdt_text(R"(97 98
-1.1190526318350336 -0.0295700799658719
-1.127040595821523 2.58677664605812e-32
-1.1186348994803028 -0.031070274220773037
-0 0
0.0005924999875309768 0.003060119597418302
0.005900942257001151 0.03269839970404613
-1.15928979137859 0.12657146213075732
-1.164541278043228 0.1377167982621452
-1.1588590721466319 0.1253398764202342
-1.1514471933856754 0.10414657161092915
-1.312537382802031 0.0987863357234447
-1.3081671488886764 0.09649197365826863
-1.2982998533483223 0.09200785314329012
-1.2930339564433908 0.09540081151002552
-1.2791123399217903 0.10538635105251822
-1.1359898113887448 0.031420582883396185
-1.1390905354312464 0.04785563708620876
-1.1438649271155947 0.06886294032592252
-1.1323412201221095 0.018267995104472568
-1.2577638965753806 0.13528147466952395
-1.2621609435092764 0.12909947198824268
-1.3162152797616047 0.1080791235872251
-1.3189248872455652 0.11604398014025166
-1.3200259491255075 0.13365495690068577
-1.3197724853148416 0.12947890236916804
-1.3194279808155345 0.12380286691593656
-1.2708924462274769 0.11682625874838913
-1.2695068080109455 0.11877394563043217
0.04009273628471606 0.1691863459079865
0.036158576263449135 0.16125019593830986
0.027838150056517363 0.13782694115451377
0.19205154606078667 0.14661940936668114
0.18445189118026373 0.14414858582254003
0.20013026134182804 0.149900172062554
0.17448420864511807 0.14989772675237623
0.16529865616032546 0.15624850546166047
0.014889905963476746 0.08015376098060058
0.012515946290854044 0.06617398636760893
0.020012867029683655 0.10395091907750036
0.01031924838296864 0.05421865378818081
0.2026802138793415 0.15606175310623402
0.20908711420116372 0.1667415947287163
0.20917920245683458 0.16937935902008378
0.20917865142664857 0.16986533606411122
0.20917441299267234 0.1736033919301927
0.15114762402633672 0.17184556100537335
0.1509556481276878 0.1720824999638254
0.15168272655307885 0.17118513104388253
0.15995959373575758 0.16210543765037025
-1.1191178497914926 -0.0309317347046944
-1.1179353355737978 -0.03142279846777766
-1.1194113874834222 -0.03072646418833412
-1.118426621709947 -0.03144208852109175
-1.1012016206428168 -0.03097041258634583
-1.0472310460782914 -0.02949252465430456
-0.3100841238741651 -0.009307070835125763
-0.001268960928292652 -0.001565346841136604
-0.0009330949977127976 -0.0013569136510521121
0.00015627077057179574 -0.0006808701420819449
0.00027539025241228045 -0.0006069464381852971
-1.118651413522495 -0.03127873344194802
-0.0008603669966018114 -0.000924240031451818
0.00031628586873674766 -1.694860349400039e-06
-1.154202977125598 0.13798687336332557
-1.1119933421318602 0.13908954695858386
-1.1428495420713733 0.13828346756632465
-1.1015437012746536 0.13936253067556928
-1.2742563729253051 0.13485062947993337
-1.3128548334957113 0.13384229327198235
-1.2771806507234957 0.1347742364025289
-1.2804261430761807 0.13468945199912272
-1.2991204074988651 0.13420108786698412
0.02012587869771957 0.16866473688093175
0.0032199497020652798 0.16822309076128242
0.18562693732560928 0.17298824376184446
0.1522325575639467 0.17211585761591489
0.1721959786924202 0.17263737686981756
0.1526340500117316 0.17212634610085262
-1.0658231782935759 0.14029568438575546
-1.0622936973193804 0.14038788763451107
-0.6828099237927111 0.15030142365439836
-0.6807110494303086 0.15035625410577583
-0.6694417589709409 0.1506506501371246
-1.1477416307445871 0.13815566790621353
-0.8824746910082686 0.1450854328801453
-0.7022086902422817 0.14979465529339037
-1.1532683266729782 0.13801128993018413
-0.6000224311589564 0.1524641427150677
-0.3593755165023077 0.15875074051700444
-0.35899362188520306 0.15876071703327885
-0.011830904129656043 0.16782990614576077
-0.02066442041195839 0.16759914164947384
-0.006805591197599202 0.16796118612197733
-0.00726531294735273 0.16794917646980434
-0.6830331881331416 0.15029559115447286
-0.34031075509486536 0.15924878341661702
-0.33535511565694626 0.15937824326048022
1 2
3 1
5 4
6 5
7 8
9 7
10 9
12 11
13 12
14 13
15 14
16 17
17 18
19 16
2 19
20 21
11 22
22 23
18 10
25 24
26 25
23 26
27 15
28 27
21 28
29 30
30 31
32 33
34 32
35 36
33 35
37 38
39 37
40 6
38 40
42 41
41 34
31 39
43 42
45 44
44 43
46 47
48 46
49 48
36 49
50 3
51 3
52 51
54 53
55 54
56 55
3 50
58 57
59 58
60 59
53 61
61 52
63 62
57 56
62 60
4 63
8 64
66 65
65 67
68 20
24 69
71 70
70 68
69 72
72 71
73 29
74 73
75 45
47 76
78 77
77 75
76 78
79 80
81 82
82 83
84 66
85 86
64 87
83 88
89 90
92 91
94 93
93 74
91 94
88 89
95 81
86 95
90 96
80 85
96 97
67 79
87 84
97 92
)");
    // The stored file's constraint indices run from 1 to 97 over its 97 points (0 never
    // occurs): they are 1-based, and are made 0-based here.
    Input zero_based = in;
    for (Segment& g : zero_based.segments) {
        ASSERT_GE(g.a, 1u);
        ASSERT_GE(g.b, 1u);
        --g.a;
        --g.b;
    }
    replay(zero_based);
}

// https://github.com/artem-ogre/CDT/pull/220 "Fix infinite loop when resolving a duplicated
// constraint edge" (regression input
// CDT/tests/inputs/hang-duplicate-constraint-edge-tryresolve.txt). CDT hung in TryResolve mode
// when the crossing of constraints lay on an end of the crossed edge. Hard: the constraint
// 0-3 is given twice, and it is crossed by the others.
TEST(ConstrainedPeerReports, CdtPr220DuplicatedConstraintHang) {
    const Input in = parse_cdt_text(R"(8 5
6 -6
7 -4
8 -8
7 5
0 7
-1 3
7 1
-6 -6
2 5
1 7
4 6
0 3
0 3
)");
    const ConstrainedTriangulation cdt = replay(in);
    // The duplicated constraint is the same chain.
    EXPECT_EQ(chain_of(cdt, 3), chain_of(cdt, 4));
}

// ---- poly2tri (C++ and its ports; sweep-line CDT of polygons) ------------------------------

// https://github.com/jhasse/poly2tri/issues/39. poly2tri failed with "EdgeEvent - null
// triangle" (eps = 1e-15; eps = 0 or negative succeeded). Hard: the polygon's vertex
// (0.5, 1e-15) is 1e-15 above the hull edge (0,0)-(1,0), which poly2tri's EPSILON calls
// collinear.
TEST(ConstrainedPeerReports, Poly2triJhasseIssue39NotQuiteCollinear) {
    Input in{{{0, 0}, {0.5, 1e-15}, {1, 0}, {1, 1}, {0, 1}}, {}};
    in.segments = path_segments(0, 5, true);
    const ConstrainedTriangulation cdt = replay(in);
    EXPECT_EQ(cdt.added_count(), 0u);
    // Five points, four on the hull: four triangles, one of them the sliver under the notch.
    EXPECT_EQ(cdt.triangulation.triangle_count(), 4u);
}

// https://github.com/greenm01/poly2tri/issues/15 (Google Code issue 15). Two quadrilaterals
// failed: in case 1 EdgeEvent's triangle->NeighborCCW(point) returned NULL, in case 2
// NextFlipPoint's Orient2d(eq, op, ep) was COLLINEAR. Hard: "when two edges get near (not
// even very near) to collinear"; the values started as floats (written here as reported).
TEST(ConstrainedPeerReports, Poly2triGreenm01Issue15NearlyCollinearQuads) {
    for (const std::vector<Point2>& quad : {
             std::vector<Point2>{
                 {-10, -10.6426}, {-28.3133, -5.98394}, {19.8795, 21.6466}, {18.4337, -5.02008}},
             std::vector<Point2>{{-4.61211, -11.3371},
                                 {-44.477, -3.90043},
                                 {25.2674, 20.9521},
                                 {23.8216, -5.71459}},
         }) {
        SCOPED_TRACE(quad[0].x);
        const Input in{quad, path_segments(0, 4, true)};
        replay(in);
    }
}

// https://github.com/greenm01/poly2tri/issues/18 (Google Code issue 18). poly2tri looped
// forever in FlipEdgeEvent and eventually crashed. Hard: a self-touching polygon; its
// vertices (1031.98..., 332), (968, 332) and (879, 332) lie on one horizontal line. The
// closing edge (1024, 512)-(1033, 309) misses vertex (1031.98..., 332) by about 1e-14: it
// crosses the edge from (968, 332) at a point that rounds onto that vertex, so exidel routes
// it through the vertex (a cascade, constrained.hpp) and its pieces are not CGAL's rounded
// ones; the result is still certified.
TEST(ConstrainedPeerReports, Poly2triGreenm01Issue18SelfTouchingPolygon) {
    Input in{{{1033, 309},
              {1032, 309.14935064935065},
              {1032, 331.55555555555617},
              {1031.9802955665025, 332},
              {968, 332},
              {968, 318.70779220779224},
              {879, 332},
              {1024, 512}},
             {}};
    in.segments = path_segments(0, 8, true);
    replay(in);
}

// https://github.com/greenm01/poly2tri/issues/49 (Google Code issue 49, JS port). poly2tri
// threw "Collinear not supported !" twice on a simple polygon without holes. Hard: a
// float32-rounded circle-like polygon whose consecutive vertices are nearly collinear.
TEST(ConstrainedPeerReports, Poly2triGreenm01Issue49CollinearNotSupported) {
    Input in{{{50, 120.5},
              {37.5, 118.70000457763672},
              {25, 113.30000305175781},
              {14.050000190734863, 105.1500015258789},
              {6.25, 95.25},
              {1.5500000715255737, 83.5},
              {0, 70},
              {1.5500000715255737, 56.45000076293945},
              {6.25, 44.70000076293945},
              {14.050000190734863, 34.79999923706055},
              {25, 26.649999618530273},
              {37.5, 21.25},
              {50, 19.450000762939453},
              {62.5, 21.25},
              {75, 26.649999618530273},
              {85.9000015258789, 34.79999923706055},
              {93.75, 44.70000076293945},
              {98.4000015258789, 56.45000076293945},
              {100, 70},
              {98.4000015258789, 83.5},
              {93.75, 95.25},
              {85.9000015258789, 105.1500015258789},
              {75, 113.30000305175781},
              {62.5, 118.70000457763672}},
             {}};
    in.segments = path_segments(0, 24, true);
    const ConstrainedTriangulation cdt = replay(in);
    EXPECT_EQ(cdt.added_count(), 0u);
}

// ---- CGAL (Constrained_triangulation_plus_2 over Epick with Exact_predicates_tag) ----------

// https://github.com/CGAL/cgal/issues/3267 ("CDT_plus_2 should prevents the insertion of
// twice the same constraint"; the points and constraints of the maintainer's reduction in
// the thread, p1..p5 and the constraints p1-p3, p3-p2, p4-p5). CGAL's
// Constrained_triangulation_plus_2 with Exact_predicates_tag (crossing points computed in
// doubles) failed on this input. Hard: five points within 2e-8 of each other (x about
// 8.7e5, y about 2.0e6, so a few ulps apart in y), three constraints among them crossing at
// points no double holds.
TEST(ConstrainedPeerReports, CgalIssue3267NearlyCoincidentConstraints) {
    const Input in{{{866874.52509081131, 2025663.1385288462},
                    {866874.52509079711, 2025663.1385288464},
                    {866874.52509081364, 2025663.1385288467},
                    {866874.52509080991, 2025663.1385288469},
                    {866874.52509081631, 2025663.1385288464}},
                   {{0, 2}, {2, 1}, {3, 4}}};
    replay(in);
}

// ---- savithru-j/cdt-js (JavaScript) ---------------------------------------------------------

// https://github.com/savithru-j/cdt-js/issues/2. cdt-js treated two collinear constraints that
// do not touch as overlapping (a wrong result). Hard: the two segments lie on one line within
// rounding, with a gap between them; they must stay two separate pieces.
TEST(ConstrainedPeerReports, CdtJsIssue2CollinearButNotTouching) {
    const Input in{{{519.03515625, 186.87890625},
                    {630.1881839273268, 256.56830560649445},
                    {741.0859375, 326.09765625},
                    {639.8512791883232, 262.62675780285144},
                    {700, 200}},
                   {{0, 1}, {2, 3}}};
    const ConstrainedTriangulation cdt = replay(in);
    EXPECT_EQ(cdt.added_count(), 0u);
    EXPECT_EQ(chain_of(cdt, 0), (std::vector<std::uint32_t>{0, 1}));
    EXPECT_EQ(chain_of(cdt, 1), (std::vector<std::uint32_t>{2, 3}));
}

}  // namespace
}  // namespace exidel::test
