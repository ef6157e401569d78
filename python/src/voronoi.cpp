// exidel._core.VoronoiData (the arrays of delaunay::voronoi and delaunay::clip; the
// scipy-like exidel.Voronoi in exidel/_voronoi.py names them) and exidel.circumcenter,
// the correctly rounded circumcentres of rows of triangles.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <pybind11/stl.h>

#include "common.hpp"
#include "exidel/delaunay/furthest.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/delaunay/voronoi.hpp"
#include "exidel/predicates/construct.hpp"

namespace exidel::python {

namespace {

template <class T>
py::array_t<T> copy_of(const std::vector<T>& v) {
    return to_numpy(std::vector<T>(v));
}
py::array_t<std::int32_t> indices_of(const std::vector<std::uint32_t>& v) {
    return to_int32(std::vector<std::uint32_t>(v));
}

/// The cell arrays both forms share, into a dict.
void cells_into(const delaunay::VoronoiCells& c, py::dict& d) {
    d["vertices"] = to_numpy(std::vector<Point2>(c.vertices));
    d["site_offsets"] = indices_of(c.site_offsets);
    d["sites"] = indices_of(c.sites);
    d["cell_offsets"] = indices_of(c.cell_offsets);
    d["cell_vertices"] = indices_of(c.cell_vertices);
    py::array_t<bool> u(static_cast<py::ssize_t>(c.unbounded.size()));
    for (std::size_t i = 0; i < c.unbounded.size(); ++i) u.mutable_data()[i] = c.unbounded[i] != 0;
    d["unbounded"] = u;
}

/// A triangulation and its Voronoi diagram, kept together so that clip() can use both.
class VoronoiData {
public:
    VoronoiData(py::object points_object, const std::string& kernel_name,
                const std::string& algorithm, unsigned threads, bool furthest) {
        const Points p = to_points(points_object, "points");
        if (p.single) throw py::value_error("points: expected shape (n, 2), got (2,)");
        if (threads == 0) throw py::value_error("threads must be at least 1");
        points_.assign(p.data, p.data + p.rows);
        const AnyKernel kernel = to_kernel(kernel_name);
        const delaunay::Options options =
            delaunay::Options{}.with_algorithm(to_algorithm(algorithm)).with_threads(threads);
        std::optional<std::string> error;
        {
            py::gil_scoped_release release;
            std::visit(
                [&](const auto& k) {
                    if (furthest) {
                        delaunay::FurthestResult r =
                            delaunay::furthest_site_triangulation(points_, k);
                        failure_ = r.failure;
                        triangulation_ = std::move(r.triangulation);
                    } else {
                        delaunay::Result r = delaunay::triangulate(points_, k, options);
                        failure_ = r.failure;
                        triangulation_ = std::move(r.triangulation);
                    }
                    if (failure_) return;
                    try {
                        diagram_ = furthest
                                       ? delaunay::furthest_site_voronoi(points_, triangulation_, k,
                                                                         threads)
                                       : delaunay::voronoi(points_, triangulation_, k, threads);
                    } catch (const delaunay::VoronoiError& e) {
                        error = e.what();
                    }
                },
                kernel);
        }
        if (error) throw py::value_error(*error);
    }

    /// The triangulation's failure (an inexact kernel), as exidel.TriangulationError's
    /// fields; None when the diagram was built.
    py::object failure() const {
        if (!failure_) return py::none();
        const delaunay::Failure& f = *failure_;
        const auto index = [](std::size_t i) {
            return i == delaunay::no_index ? py::object(py::none()) : py::object(py::int_(i));
        };
        return py::make_tuple(std::string(delaunay::to_string(f.kind)), index(f.input_index),
                              index(f.insertion), f.message);
    }

    py::dict arrays() const {
        py::dict d;
        cells_into(diagram_, d);
        d["entry_ray"] = to_numpy(std::vector<Point2>(diagram_.entry_ray));
        d["exit_ray"] = to_numpy(std::vector<Point2>(diagram_.exit_ray));
        d["vertex_of_triangle"] = indices_of(diagram_.vertex_of_triangle);
        d["collinear"] = diagram_.collinear;
        d["chain"] = indices_of(diagram_.chain);
        const auto m = static_cast<py::ssize_t>(triangulation_.triangle_count());
        d["triangles"] = to_int32(std::vector<std::uint32_t>(triangulation_.triangles), {m, 3});
        d["halfedges"] = copy_of(triangulation_.halfedges);
        d["vertex_of_input"] = indices_of(triangulation_.vertex_of_input);
        py::dict stats;
        stats["stage_float"] = diagram_.stage_counts[0];
        stats["stage_double_word"] = diagram_.stage_counts[1];
        stats["stage_exact"] = diagram_.stage_counts[2];
        stats["cocircular_tests"] = diagram_.cocircular_tests;
        stats["cocircular_merges"] = diagram_.cocircular_merges;
        d["stats"] = stats;
        return d;
    }

    py::dict clip(double xmin, double ymin, double xmax, double ymax) const {
        delaunay::ClippedVoronoi c;
        {
            py::gil_scoped_release release;
            c = delaunay::clip(diagram_, points_, triangulation_,
                               delaunay::Box{xmin, ymin, xmax, ymax});
        }
        py::dict d;
        cells_into(c, d);
        d["voronoi_vertex_count"] = c.voronoi_vertex_count;
        return d;
    }

private:
    std::vector<Point2> points_;
    std::optional<delaunay::Failure> failure_;
    delaunay::Triangulation triangulation_;
    delaunay::VoronoiDiagram diagram_;
};

/// Python lists of Python ints, values[offsets[k]:offsets[k + 1]] for every k, with -1
/// appended where tail[k] (scipy's regions: -1 marks an unbounded cell). Built with the
/// C API: through numpy slices and list(), the regions of 171k cells took seconds.
py::list split_lists(
    py::array_t<std::int32_t, py::array::c_style | py::array::forcecast> offsets,
    py::array_t<std::int32_t, py::array::c_style | py::array::forcecast> values,
    std::optional<py::array_t<bool, py::array::c_style | py::array::forcecast>> tail) {
    const std::size_t n = offsets.size() > 0 ? static_cast<std::size_t>(offsets.size()) - 1 : 0;
    if (tail && static_cast<std::size_t>(tail->size()) != n) {
        throw py::value_error("tail: one flag per list expected");
    }
    const std::int32_t* o = offsets.data();
    const std::int32_t* v = values.data();
    const auto size = static_cast<std::int64_t>(values.size());
    PyObject* out = PyList_New(static_cast<Py_ssize_t>(n));
    if (!out) throw py::error_already_set();
    py::list result = py::reinterpret_steal<py::list>(out);
    for (std::size_t k = 0; k < n; ++k) {
        if (o[k] < 0 || o[k] > o[k + 1] || o[k + 1] > size) {
            throw py::value_error("offsets must increase within the values");
        }
        const bool minus_one = tail && tail->data()[k];
        const Py_ssize_t length = o[k + 1] - o[k] + (minus_one ? 1 : 0);
        PyObject* inner = PyList_New(length);
        if (!inner) throw py::error_already_set();
        PyList_SET_ITEM(out, static_cast<Py_ssize_t>(k), inner);  // steals; freed with out
        for (Py_ssize_t j = 0; j < length; ++j) {
            const long value = minus_one && j + 1 == length ? -1L : long{v[o[k] + j]};
            PyObject* item = PyLong_FromLong(value);
            if (!item) throw py::error_already_set();
            PyList_SET_ITEM(inner, j, item);
        }
    }
    return result;
}

py::tuple circumcenter_rows(py::object a_object, py::object b_object, py::object c_object) {
    const std::array<Points, 3> p{to_points(a_object, "a"), to_points(b_object, "b"),
                                  to_points(c_object, "c")};
    const std::array<const char*, 3> names{"a", "b", "c"};
    const auto [rows, shaped] = broadcast(p, names);
    std::vector<Point2> centres(rows);
    std::vector<std::int8_t> status(rows);
    {
        py::gil_scoped_release release;
        const auto at = [](const Points& p, std::size_t i) { return p.data[p.rows == 1 ? 0 : i]; };
        for (std::size_t i = 0; i < rows; ++i) {
            const Circumcenter r = circumcenter(at(p[0], i), at(p[1], i), at(p[2], i));
            centres[i] = r.point;
            status[i] = static_cast<std::int8_t>(r.status);
        }
    }
    py::array_t<double> out = to_numpy(std::move(centres));
    py::array_t<std::int8_t> st = to_numpy(std::move(status));
    if (!shaped) return py::make_tuple(out.attr("reshape")(2), st.attr("reshape")(py::tuple()));
    return py::make_tuple(out, st);
}

}  // namespace

void bind_voronoi(py::module_& m) {
    py::class_<VoronoiData>(m, "VoronoiData")
        .def(py::init<py::object, const std::string&, const std::string&, unsigned, bool>(),
             py::arg("points"), py::arg("kernel") = "adaptive", py::arg("algorithm") = "external",
             py::arg("threads") = 1, py::arg("furthest") = false)
        .def("failure", &VoronoiData::failure)
        .def("arrays", &VoronoiData::arrays)
        .def("clip", &VoronoiData::clip, py::arg("xmin"), py::arg("ymin"), py::arg("xmax"),
             py::arg("ymax"));
    m.def("split_lists", &split_lists, py::arg("offsets"), py::arg("values"),
          py::arg("tail") = py::none(),
          "[values[offsets[k]:offsets[k+1]] (+ [-1] where tail[k]) for every k], as lists of "
          "ints.");
    py::list statuses;
    for (auto s : {CircumcenterStatus::ok, CircumcenterStatus::collinear,
                   CircumcenterStatus::overflow, CircumcenterStatus::non_finite_input}) {
        statuses.append(py::str(std::string(to_string(s))));
    }
    m.attr("circumcenter_statuses") = statuses;
    m.def("circumcenter", &circumcenter_rows, py::arg("a"), py::arg("b"), py::arg("c"),
          "Correctly rounded circumcentres of the triangles (a[i], b[i], c[i]): each coordinate "
          "the double nearest to the exact one. Returns (centres (n, 2) float64, status (n,) int8 "
          "indexing exidel.circumcenter_statuses: ok, collinear (NaN, NaN), overflow (+-inf)). "
          "Arguments as for exidel.orient2d.");
}

}  // namespace exidel::python
