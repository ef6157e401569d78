// exidel._core.constrained_delaunay and certify_constrained: a delaunay::ConstrainedResult
// and its delaunay::Regions as numpy arrays in a dict, and the constrained certifier over
// such a dict. exidel.ConstrainedDelaunay (exidel/_constrained.py) gives them names.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <pybind11/stl.h>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "common.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/constrained.hpp"
#include "exidel/delaunay/regions.hpp"

namespace exidel::python {

namespace {

using delaunay::Segment;

/// An integer array, C-contiguous (numpy converts other dtypes and layouts once).
using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

IndexArray to_index_array(const py::handle& object, const char* argument) {
    IndexArray a;
    try {
        a = IndexArray::ensure(object);
    } catch (const py::error_already_set&) {
        a = IndexArray();
    }
    if (!a) throw py::value_error(std::string(argument) + ": not convertible to an integer array");
    return a;
}

std::string shape_of(const py::array& a) {
    std::string shape = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) {
        shape += (k ? ", " : "") + std::to_string(a.shape(k));
    }
    return shape + (a.ndim() == 1 ? ",)" : ")");
}

/// One index in [0, 2^32): anything else becomes 2^32 - 1, an index every check reports
/// as out of range.
std::uint32_t to_index(std::int64_t v) {
    return v < 0 || v > 0xffffffffLL ? 0xffffffffu : static_cast<std::uint32_t>(v);
}

/// An (n,) index array (any shape is read flat).
std::vector<std::uint32_t> flat_indices(const py::handle& object, const char* argument) {
    const IndexArray a = to_index_array(object, argument);
    std::vector<std::uint32_t> out(static_cast<std::size_t>(a.size()));
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = to_index(a.data()[i]);
    return out;
}

/// An (n, W) index array as rows; an empty array of any shape is no rows.
template <std::size_t W>
std::vector<std::array<std::uint32_t, W>> index_rows(const py::handle& object,
                                                     const char* argument) {
    const IndexArray a = to_index_array(object, argument);
    if (a.size() == 0) return {};
    if (a.ndim() != 2 || a.shape(1) != static_cast<py::ssize_t>(W)) {
        throw py::value_error(std::string(argument) + ": expected shape (n, " + std::to_string(W) +
                              "), got " + shape_of(a));
    }
    std::vector<std::array<std::uint32_t, W>> out(static_cast<std::size_t>(a.shape(0)));
    for (std::size_t i = 0; i < out.size(); ++i) {
        for (std::size_t k = 0; k < W; ++k) out[i][k] = to_index(a.data()[W * i + k]);
    }
    return out;
}

/// Rows of W indices as an (n, W) int32 array.
template <std::size_t W>
py::array_t<std::int32_t> rows_to_numpy(const std::vector<std::array<std::uint32_t, W>>& rows) {
    std::vector<std::uint32_t> flat;
    flat.reserve(W * rows.size());
    for (const auto& row : rows) flat.insert(flat.end(), row.begin(), row.end());
    return to_int32(std::move(flat),
                    {static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(W)});
}

py::object index_or_none(std::size_t i) {
    return i == delaunay::no_index ? py::object(py::none()) : py::object(py::int_(i));
}

py::dict failure_dict(const delaunay::Failure& f) {
    py::dict failure;
    failure["kind"] = std::string(delaunay::to_string(f.kind));
    failure["input_index"] = index_or_none(f.input_index);
    failure["insertion"] = index_or_none(f.insertion);
    failure["message"] = f.message;
    return failure;
}

delaunay::FillRule to_rule(const std::string& name) {
    if (name == "even_odd") return delaunay::FillRule::even_odd;
    if (name == "non_zero") return delaunay::FillRule::non_zero;
    if (name == "enclosed") return delaunay::FillRule::enclosed;
    if (name == "all") return delaunay::FillRule::all;
    throw py::value_error("unknown rule '" + name + "'; expected even_odd|non_zero|enclosed|all");
}

/// The segments, an (m, 2) integer array (an empty array of any shape: none). An index
/// outside [0, points) is the library's invalid_segment failure, with the segment's position.
std::vector<Segment> to_segments(const py::handle& object, std::size_t points,
                                 std::optional<delaunay::Failure>& failure) {
    const IndexArray a = to_index_array(object, "segments");
    if (a.size() == 0) return {};
    if (a.ndim() != 2 || a.shape(1) != 2) {
        throw py::value_error("segments: expected shape (m, 2), got " + shape_of(a));
    }
    std::vector<Segment> out(static_cast<std::size_t>(a.shape(0)));
    const std::int64_t* d = a.data();
    const auto n = static_cast<std::int64_t>(points);
    for (std::size_t s = 0; s < out.size(); ++s) {
        for (const std::int64_t v : {d[2 * s], d[2 * s + 1]}) {
            if (v >= 0 && v < n) continue;
            failure =
                delaunay::Failure{delaunay::FailureKind::invalid_segment, s, delaunay::no_index,
                                  "segment " + std::to_string(s) + " names point " +
                                      std::to_string(v) + " of " + std::to_string(points)};
            return {};
        }
        out[s] = {static_cast<std::uint32_t>(d[2 * s]), static_cast<std::uint32_t>(d[2 * s + 1])};
    }
    return out;
}

/// The constrained triangulation's arrays and the regions under `rule` with hole seeds
/// `holes`, or 'failure'.
py::dict constrained(py::object points_object, py::object segments_object,
                     const std::string& kernel_name, const std::string& algorithm,
                     py::object holes_object, const std::string& rule, std::size_t max_added_points,
                     py::object attributes_object) {
    const Points points = to_points(points_object, "points");
    if (points.single) throw py::value_error("points: expected shape (n, 2), got (2,)");
    if (points.rows > delaunay::detail::max_points) {
        throw py::value_error("points: " + std::to_string(points.rows) + " rows; at most " +
                              std::to_string(delaunay::detail::max_points) + " are supported");
    }
    std::optional<delaunay::Failure> bad_segment;
    const std::vector<Segment> segments = to_segments(segments_object, points.rows, bad_segment);
    const AnyKernel kernel = to_kernel(kernel_name);
    delaunay::ConstrainedOptions options;
    options.delaunay = delaunay::Options{}.with_algorithm(to_algorithm(algorithm));
    options.max_added_points = max_added_points;
    delaunay::RegionOptions region_options;
    region_options.rule = to_rule(rule);
    if (!holes_object.is_none()) {
        const Points holes = to_points(holes_object, "holes");
        region_options.holes.assign(holes.data, holes.data + holes.rows);
    }
    if (!attributes_object.is_none()) {
        // Rows (x, y, value), checked finite by the Python side.
        const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(
            attributes_object);
        if (!a || (a.size() != 0 && (a.ndim() != 2 || a.shape(1) != 3)))
            throw py::value_error("attributes: expected shape (a, 3)");
        for (py::ssize_t i = 0; a.size() != 0 && i < a.shape(0); ++i)
            region_options.attributes.push_back({{a.at(i, 0), a.at(i, 1)}, a.at(i, 2)});
    }
    py::dict d;
    if (bad_segment) {
        d["failure"] = failure_dict(*bad_segment);
        return d;
    }
    delaunay::ConstrainedResult result;
    delaunay::Regions regions;
    {
        py::gil_scoped_release release;
        result = std::visit(
            [&](const auto& k) {
                return delaunay::constrained_delaunay(points.span(), segments, k, options);
            },
            kernel);
        if (result.ok()) regions = delaunay::classify_regions(result.cdt, region_options);
    }
    if (!result.ok()) {
        d["failure"] = failure_dict(*result.failure);
        return d;
    }
    delaunay::ConstrainedTriangulation& cdt = result.cdt;
    d["input_count"] = cdt.input_count;
    d["points"] = to_numpy(std::move(cdt.points));
    triangulation_arrays(std::move(cdt.triangulation), d);
    d["chain_offsets"] = to_int32(std::move(cdt.chain_offsets));
    d["chain_vertices"] = to_int32(std::move(cdt.chain_vertices));
    d["crossings"] = rows_to_numpy(cdt.crossings);
    d["crossing_lines"] = rows_to_numpy(cdt.crossing_lines);
    d["constraints"] = rows_to_numpy(cdt.constraints);

    const auto t = static_cast<py::ssize_t>(regions.inside.size());
    d["region"] = to_int32(std::move(regions.region));
    d["depth"] = to_int32(std::move(regions.depth));
    d["winding"] = to_numpy(std::move(regions.winding));
    py::array_t<bool> inside(t);
    for (py::ssize_t i = 0; i < t; ++i) {
        inside.mutable_at(i) = regions.inside[static_cast<std::size_t>(i)] != 0;
    }
    d["inside"] = inside;
    d["region_count"] = regions.region_count;
    d["closed"] = regions.closed;
    std::vector<std::int64_t> unplaced(regions.unplaced_holes.begin(),
                                       regions.unplaced_holes.end());
    d["unplaced_holes"] = to_numpy(std::move(unplaced));
    d["attribute"] = to_numpy(std::move(regions.attribute));
    std::vector<std::int64_t> unplaced_attributes(regions.unplaced_attributes.begin(),
                                                  regions.unplaced_attributes.end());
    d["unplaced_attributes"] = to_numpy(std::move(unplaced_attributes));
    return d;
}

/// certify_constrained over the arrays of `cdt` (constrained()'s keys), as certify's dict.
py::dict certify_constrained(py::object points_object, py::object segments_object,
                             const py::dict& cdt, std::int64_t max_findings) {
    const Points input = to_points(points_object, "points");
    if (input.single) throw py::value_error("points: expected shape (n, 2), got (2,)");
    // The segments as given, out-of-range ones included (the certifier reports them).
    std::vector<Segment> segments;
    for (const auto& row : index_rows<2>(segments_object, "segments")) {
        segments.push_back({row[0], row[1]});
    }
    const auto get = [&](const char* key) -> py::object {
        if (!cdt.contains(key)) throw py::value_error(std::string("cdt: no '") + key + "'");
        return cdt[key];
    };
    delaunay::ConstrainedTriangulation c;
    const Points all = to_points(get("points"), "cdt points");
    if (all.single) throw py::value_error("cdt points: expected shape (n, 2), got (2,)");
    c.points.assign(all.data, all.data + all.rows);
    c.input_count = get("input_count").cast<std::size_t>();
    delaunay::Triangulation& t = c.triangulation;
    t.triangles = flat_indices(get("triangles"), "triangles");
    {
        const IndexArray h = to_index_array(get("halfedges"), "halfedges");
        t.halfedges.resize(static_cast<std::size_t>(h.size()));
        for (std::size_t i = 0; i < t.halfedges.size(); ++i) {
            const std::int64_t v = h.data()[i];
            // Out of [-1, 2^31): an index the certifier reports as out of range.
            t.halfedges[i] = v < -1 || v > 0x7fffffffLL ? std::int32_t{0x7fffffff}
                                                        : static_cast<std::int32_t>(v);
        }
    }
    t.hull = flat_indices(get("hull"), "hull");
    t.vertex_of_input = flat_indices(get("vertex_of_input"), "vertex_of_input");
    t.duplicates = flat_indices(get("duplicates"), "duplicates");
    t.collinear = get("collinear").cast<bool>();
    c.chain_offsets = flat_indices(get("chain_offsets"), "chain_offsets");
    c.chain_vertices = flat_indices(get("chain_vertices"), "chain_vertices");
    c.crossings = index_rows<2>(get("crossings"), "crossings");
    c.crossing_lines = index_rows<4>(get("crossing_lines"), "crossing_lines");
    c.constraints = index_rows<2>(get("constraints"), "constraints");

    delaunay::CertifyOptions options;
    options.max_findings =
        max_findings >= 0 ? static_cast<std::size_t>(max_findings) : static_cast<std::size_t>(-1);
    delaunay::Certificate cert;
    {
        py::gil_scoped_release release;
        cert = delaunay::certify_constrained(input.span(), segments, c, options);
    }
    return certificate_dict(cert, py::list(), t.triangle_count());
}

}  // namespace

void bind_constrained(py::module_& m) {
    m.def("constrained_delaunay", &constrained, py::arg("points"), py::arg("segments"),
          py::arg("kernel") = "adaptive", py::arg("algorithm") = "external",
          py::arg("holes") = py::none(), py::arg("rule") = "even_odd",
          py::arg("max_added_points") = 0, py::arg("attributes") = py::none(),
          "The constrained Delaunay triangulation's arrays (points with the added crossing "
          "points, input_count, triangles (m, 3), halfedges, hull, vertex_of_input, "
          "duplicates, collinear, chain_offsets, chain_vertices, crossings (k, 2), "
          "crossing_lines (k, 4), constraints (c, 2)) and its regions under the fill rule "
          "(even_odd|non_zero|enclosed|all) and hole seeds (region, depth, winding, inside, "
          "region_count, closed, unplaced_holes); or 'failure'. max_added_points 0: no limit "
          "but the indices'. exidel.ConstrainedDelaunay wraps this.");
    m.def("certify_constrained", &certify_constrained, py::arg("points"), py::arg("segments"),
          py::arg("cdt"), py::arg("max_findings") = 64,
          "delaunay::certify_constrained over the arrays of a constrained_delaunay dict, for "
          "the input points and segments: certify's dict (ok, total_findings, findings, "
          "notes, triangles). max_findings < 0 keeps every finding.");
}

}  // namespace exidel::python
