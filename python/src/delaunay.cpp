// exidel._core.triangulate and certify: the arrays of a delaunay::Result and a
// delaunay::Certificate as numpy arrays and dicts. exidel.Delaunay (exidel/_delaunay.py)
// gives them scipy's names.
#include <algorithm>
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
#include "exidel/delaunay/furthest.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace exidel::python {

void triangulation_arrays(delaunay::Triangulation&& t, py::dict& d) {
    const auto m = static_cast<py::ssize_t>(t.triangle_count());
    d["triangles"] = to_int32(std::move(t.triangles), {m, 3});
    d["halfedges"] = to_numpy(std::move(t.halfedges));
    d["hull"] = to_int32(std::move(t.hull));
    d["vertex_of_input"] = to_int32(std::move(t.vertex_of_input));
    d["duplicates"] = to_int32(std::move(t.duplicates));
    d["collinear"] = t.collinear;
}

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
    d["cavity_pieces"] = r.cavity_pieces;
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
    triangulation_arrays(std::move(r.triangulation), d);
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

/// The furthest-site triangulation as triangulate's dict (algorithm "furthest-site").
py::dict furthest_site(py::object points_object, const std::string& kernel_name) {
    const Points points = to_points(points_object, "points");
    if (points.single) throw py::value_error("points: expected shape (n, 2), got (2,)");
    const AnyKernel kernel = to_kernel(kernel_name);
    delaunay::FurthestResult furthest;
    {
        py::gil_scoped_release release;
        furthest = std::visit(
            [&](const auto& k) { return delaunay::furthest_site_triangulation(points.span(), k); },
            kernel);
    }
    py::dict d = result_dict(std::move(furthest).to_result(), false);
    d["algorithm"] = "furthest-site";
    d["strategy"] = "none";
    return d;
}

// ---------------------------------------------------------------------------------
// Certifying what any producer wrote: its arrays go through delaunay::normalize (the
// conventions of delaunator, scipy, Triangle, CGAL) and the certifier, as in
// `exidel certify`.

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

py::dict certify_produced(py::object points_object, IndexArray triangles,
                          std::optional<IndexArray> halfedges, std::optional<IndexArray> hull,
                          std::optional<IndexArray> duplicates, bool strict,
                          std::int64_t max_findings) {
    const Points points = to_points(points_object, "points");
    if (points.single) throw py::value_error("points: expected shape (n, 2), got (2,)");
    delaunay::ProducedTriangulation produced;
    produced.triangles = to_indices(triangles);
    if (halfedges) {
        std::vector<std::int32_t> h(static_cast<std::size_t>(halfedges->size()));
        for (std::size_t i = 0; i < h.size(); ++i) {
            const std::int64_t v = halfedges->data()[i];
            // Out of [-1, 2^31): an index the certifier reports as out of range.
            h[i] = v < -1 || v > 0x7fffffffLL ? std::int32_t{0x7fffffff}
                                              : static_cast<std::int32_t>(v);
        }
        produced.halfedges = std::move(h);
    }
    if (hull) produced.hull = to_indices(*hull);
    if (duplicates) produced.duplicates = to_indices(*duplicates);
    delaunay::Normalization normalization;
    delaunay::Certificate c;
    std::size_t triangle_count = 0;
    {
        py::gil_scoped_release release;
        const delaunay::Triangulation t =
            delaunay::normalize(points.span(), std::move(produced), &normalization, strict);
        triangle_count = t.triangle_count();
        delaunay::CertifyOptions options;
        if (max_findings >= 0)
            options.max_findings = static_cast<std::size_t>(max_findings);
        else
            options.max_findings = static_cast<std::size_t>(-1);
        c = delaunay::certify(points.span(), t, options);
    }
    return certificate_dict(c, py::cast(normalization.notes()), triangle_count);
}

}  // namespace

void bind_delaunay(py::module_& m) {
    m.def("triangulate", &triangulate, py::arg("points"), py::arg("kernel") = "adaptive",
          py::arg("algorithm") = "external", py::arg("incircle") = "determinant",
          py::arg("order") = "auto", py::arg("threads") = 1, py::arg("counters") = false,
          "The Delaunay triangulation's arrays (triangles (m, 3), halfedges, hull, "
          "vertex_of_input, duplicates, collinear), or 'failure' when an inexact kernel "
          "contradicted itself. exidel.Delaunay wraps this.");
    m.def("furthest_site", &furthest_site, py::arg("points"), py::arg("kernel") = "adaptive",
          "The furthest-site Delaunay triangulation's arrays, as triangulate's.");
    m.def("certify", &certify_produced, py::arg("points"), py::arg("triangles"),
          py::arg("halfedges") = py::none(), py::arg("hull") = py::none(),
          py::arg("duplicates") = py::none(), py::arg("strict") = false,
          py::arg("max_findings") = 64,
          "delaunay::normalize then delaunay::certify: a dict with ok, total_findings, "
          "findings (kind, message, triangle, points, index, other), notes, triangles. "
          "max_findings < 0 keeps every finding. exidel.certify wraps this.");
}

}  // namespace exidel::python
