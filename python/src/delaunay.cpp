// exidel._core.triangulate and certify: the arrays of a delaunay::Result and a
// delaunay::Certificate as numpy arrays and dicts. exidel.Delaunay (exidel/_delaunay.py)
// gives them scipy's names.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

#include "common.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace exidel::python {

namespace {

using delaunay::Algorithm;
using delaunay::InCirclePolicy;
using delaunay::Strategy;

delaunay::Options to_options(const std::string& algorithm, const std::string& incircle,
                             const std::string& strategy, unsigned threads) {
    const Algorithm a = to_algorithm(algorithm);
    InCirclePolicy policy = InCirclePolicy::determinant;
    if (incircle == "cosine") {
        policy = InCirclePolicy::cosine;
    } else if (incircle != "determinant") {
        throw py::value_error("unknown incircle '" + incircle + "'; expected determinant|cosine");
    }
    std::optional<Strategy> order;
    if (strategy == "auto") order = Strategy::automatic;
    for (Strategy s : {Strategy::lexicographic, Strategy::radial, Strategy::strips}) {
        if (strategy == delaunay::to_string(s)) order = s;
    }
    if (!order) {
        throw py::value_error("unknown order '" + strategy +
                              "'; expected auto|lexicographic|radial|strips");
    }
    if (threads == 0) throw py::value_error("threads must be at least 1");
    return delaunay::Options{}
        .with_algorithm(a)
        .with_incircle(policy)
        .with_strategy(*order)
        .with_threads(threads);
}

py::dict counters_dict(const delaunay::Counters& c) {
    py::dict d;
    c.for_each(
        [&](std::string_view name, std::uint64_t value) { d[py::str(std::string(name))] = value; });
    return d;
}

/// The result's arrays (shape (m, 3) for the triangles), or its failure.
py::dict result_dict(delaunay::Result&& r, bool counters) {
    py::dict d;
    d["algorithm"] = std::string(delaunay::to_string(r.algorithm));
    d["strategy"] = std::string(delaunay::to_string(r.strategy));
    d["strips"] = r.strips;
    if (counters) d["counters"] = counters_dict(r.counters);
    if (r.failure) {
        const delaunay::Failure& f = *r.failure;
        py::dict failure;
        failure["kind"] = std::string(delaunay::to_string(f.kind));
        failure["input_index"] = f.input_index == delaunay::no_index
                                     ? py::object(py::none())
                                     : py::object(py::int_(f.input_index));
        failure["insertion"] = f.insertion == delaunay::no_index
                                   ? py::object(py::none())
                                   : py::object(py::int_(f.insertion));
        failure["message"] = f.message;
        d["failure"] = failure;
        return d;
    }
    delaunay::Triangulation& t = r.triangulation;
    const auto m = static_cast<py::ssize_t>(t.triangle_count());
    d["triangles"] = to_int32(std::move(t.triangles), {m, 3});
    d["halfedges"] = to_numpy(std::move(t.halfedges));
    d["hull"] = to_int32(std::move(t.hull));
    d["vertex_of_input"] = to_int32(std::move(t.vertex_of_input));
    d["duplicates"] = to_int32(std::move(t.duplicates));
    d["collinear"] = t.collinear;
    return d;
}

py::dict triangulate(py::object points_object, const std::string& kernel_name,
                     const std::string& algorithm, const std::string& incircle,
                     const std::string& strategy, unsigned threads, bool counters) {
    const Points points = to_points(points_object, "points");
    if (points.single) throw py::value_error("points: expected shape (n, 2), got (2,)");
    if (points.rows > delaunay::detail::max_points) {
        throw py::value_error("points: " + std::to_string(points.rows) + " rows; at most " +
                              std::to_string(delaunay::detail::max_points) + " are supported");
    }
    const AnyKernel kernel = to_kernel(kernel_name);
    const delaunay::Options options = to_options(algorithm, incircle, strategy, threads);
    delaunay::Result result;
    {
        py::gil_scoped_release release;
        result = std::visit(
            [&](const auto& k) {
                return counters ? delaunay::triangulate<delaunay::Instrumentation::counters>(
                                      points.span(), k, options)
                                : delaunay::triangulate(points.span(), k, options);
            },
            kernel);
    }
    return result_dict(std::move(result), counters);
}

// ---------------------------------------------------------------------------------
// Certifying a bare list of triangles (scipy's simplices, a user's mesher): the rest of
// a Triangulation is derived from them, as faithfully as the input allows; whatever
// cannot be derived (an index out of range, an edge of three triangles, a boundary that
// is not one cycle) is left for the certifier to report.

/// For every input index the index of the first equal point, and the repeats.
void vertex_map(std::span<const Point2> p, delaunay::Triangulation& t) {
    std::vector<std::uint32_t> order(p.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return p[a].x < p[b].x || (p[a].x == p[b].x && p[a].y < p[b].y);
    });
    t.vertex_of_input.assign(p.size(), 0);
    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::uint32_t i = order[k];
        const bool repeat = k > 0 && p[order[k - 1]] == p[i];
        t.vertex_of_input[i] = repeat ? t.vertex_of_input[order[k - 1]] : i;
        if (repeat) t.duplicates.push_back(i);
    }
    std::sort(t.duplicates.begin(), t.duplicates.end());
}

/// Twins by matching reversed edges; the boundary cycle from the lexicographically
/// smallest vertex with an outgoing boundary half-edge.
void derive_topology(std::span<const Point2> p, delaunay::Triangulation& t) {
    const std::size_t e_count = t.triangles.size();
    t.halfedges.assign(e_count, -1);
    const auto key = [](std::uint64_t a, std::uint64_t b) { return (a << 32) | b; };
    std::unordered_map<std::uint64_t, std::uint32_t> edge;
    edge.reserve(e_count);
    for (std::size_t e = 0; e < e_count; ++e) {
        edge.emplace(key(t.triangles[e], t.triangles[delaunay::next_halfedge(e)]),
                     static_cast<std::uint32_t>(e));
    }
    for (std::size_t e = 0; e < e_count; ++e) {
        if (t.halfedges[e] >= 0) continue;
        const auto it = edge.find(key(t.triangles[delaunay::next_halfedge(e)], t.triangles[e]));
        if (it == edge.end() || t.halfedges[it->second] >= 0 || it->second == e) continue;
        t.halfedges[e] = static_cast<std::int32_t>(it->second);
        t.halfedges[it->second] = static_cast<std::int32_t>(e);
    }
    std::unordered_map<std::uint32_t, std::uint32_t> boundary_from;  // start vertex -> end
    std::optional<std::uint32_t> first;
    for (std::size_t e = 0; e < e_count; ++e) {
        if (t.halfedges[e] >= 0) continue;
        const std::uint32_t a = t.triangles[e];
        boundary_from.emplace(a, t.triangles[delaunay::next_halfedge(e)]);
        if (!first || p[a].x < p[*first].x || (p[a].x == p[*first].x && p[a].y < p[*first].y))
            first = a;
    }
    if (!first) return;
    std::uint32_t v = *first;
    for (std::size_t steps = 0; steps <= boundary_from.size(); ++steps) {
        t.hull.push_back(v);
        const auto it = boundary_from.find(v);
        if (it == boundary_from.end() || it->second == *first) break;
        v = it->second;
    }
}

/// The distinct points lexicographically (first occurrences): the chain of a result with
/// no triangles.
std::vector<std::uint32_t> lexicographic_chain(std::span<const Point2> p,
                                               const delaunay::Triangulation& t) {
    std::vector<std::uint32_t> chain;
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        if (t.vertex_of_input[i] == i) chain.push_back(i);
    }
    std::sort(chain.begin(), chain.end(), [&](std::uint32_t a, std::uint32_t b) {
        return p[a].x < p[b].x || (p[a].x == p[b].x && p[a].y < p[b].y);
    });
    return chain;
}

py::dict certificate_dict(const delaunay::Certificate& c) {
    py::list findings;
    for (const delaunay::Finding& f : c.findings) {
        py::dict d;
        d["kind"] = std::string(delaunay::to_string(f.kind));
        d["index"] = f.index;
        d["other"] = f.other;
        d["message"] = f.message;
        findings.append(d);
    }
    py::dict d;
    d["ok"] = c.ok();
    d["total_findings"] = c.total_findings;
    d["findings"] = findings;
    return d;
}

using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

std::vector<std::uint32_t> to_indices(const IndexArray& a) {
    std::vector<std::uint32_t> out(static_cast<std::size_t>(a.size()));
    const std::int64_t* d = a.data();
    for (std::size_t i = 0; i < out.size(); ++i) {
        // Anything outside [0, 2^32) becomes an index the certifier reports as out of range.
        out[i] = d[i] < 0 || d[i] > 0xffffffffLL ? 0xffffffffu : static_cast<std::uint32_t>(d[i]);
    }
    return out;
}

py::dict certify_simplices(py::object points_object, IndexArray simplices, bool reorient) {
    const Points points = to_points(points_object, "points");
    if (points.single) throw py::value_error("points: expected shape (n, 2), got (2,)");
    if (!(simplices.ndim() == 2 && simplices.shape(1) == 3) &&
        !(simplices.ndim() == 1 && simplices.shape(0) == 0)) {
        throw py::value_error("simplices: expected an integer array of shape (m, 3)");
    }
    const std::span<const Point2> p = points.span();
    delaunay::Triangulation t;
    t.triangles = to_indices(simplices);
    delaunay::Certificate c;
    {
        py::gil_scoped_release release;
        vertex_map(p, t);
        const bool in_range = std::all_of(t.triangles.begin(), t.triangles.end(),
                                          [&](std::uint32_t v) { return v < p.size(); });
        if (t.triangles.empty()) {
            t.collinear = true;
            t.hull = lexicographic_chain(p, t);
        } else if (in_range) {
            // Any copy of a repeated point may stand for it (scipy uses whichever copy
            // qhull kept): the certifier's vertices are first occurrences.
            for (std::uint32_t& v : t.triangles) v = t.vertex_of_input[v];
            if (reorient) {
                for (std::size_t i = 0; i < t.triangles.size(); i += 3) {
                    auto* v = &t.triangles[i];
                    if (AdaptiveKernel::orient2d(p[v[0]], p[v[1]], p[v[2]]) == Sign::negative) {
                        std::swap(v[1], v[2]);
                    }
                }
            }
            derive_topology(p, t);
        } else {
            t.halfedges.assign(t.triangles.size(), -1);
        }
        c = delaunay::certify(p, t);
    }
    return certificate_dict(c);
}

py::dict certify_arrays(py::object points_object, IndexArray triangles, IndexArray halfedges,
                        IndexArray hull, IndexArray vertex_of_input, IndexArray duplicates,
                        bool collinear) {
    const Points points = to_points(points_object, "points");
    delaunay::Triangulation t;
    t.triangles = to_indices(triangles);
    t.halfedges.resize(static_cast<std::size_t>(halfedges.size()));
    for (std::size_t i = 0; i < t.halfedges.size(); ++i) {
        const std::int64_t h = halfedges.data()[i];
        t.halfedges[i] =
            h < -1 || h > 0x7fffffffLL ? std::int32_t{0x7fffffff} : static_cast<std::int32_t>(h);
    }
    t.hull = to_indices(hull);
    t.vertex_of_input = to_indices(vertex_of_input);
    t.duplicates = to_indices(duplicates);
    t.collinear = collinear;
    delaunay::Certificate c;
    {
        py::gil_scoped_release release;
        c = delaunay::certify(points.span(), t);
    }
    return certificate_dict(c);
}

}  // namespace

void bind_delaunay(py::module_& m) {
    m.def("triangulate", &triangulate, py::arg("points"), py::arg("kernel") = "adaptive",
          py::arg("algorithm") = "external", py::arg("incircle") = "determinant",
          py::arg("order") = "auto", py::arg("threads") = 1, py::arg("counters") = false,
          "The Delaunay triangulation's arrays (triangles (m, 3), halfedges, hull, "
          "vertex_of_input, duplicates, collinear), or 'failure' when an inexact kernel "
          "contradicted itself. exidel.Delaunay wraps this.");
    m.def("certify_simplices", &certify_simplices, py::arg("points"), py::arg("simplices"),
          py::arg("reorient") = true);
    m.def("certify_arrays", &certify_arrays, py::arg("points"), py::arg("triangles"),
          py::arg("halfedges"), py::arg("hull"), py::arg("vertex_of_input"), py::arg("duplicates"),
          py::arg("collinear"));
}

}  // namespace exidel::python
