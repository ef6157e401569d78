// exidel._core.Locator: exact point location (delaunay::Locator) over the arrays of an
// exidel.Delaunay, kept between calls (its walk-ordered copy of the mesh is built once).
// exidel.Delaunay.locate and find_simplex (exidel/_delaunay.py) use it.
#include <pybind11/stl.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "common.hpp"
#include "exidel/delaunay/locate.hpp"
#include "exidel/delaunay/natural.hpp"
#include "exidel/delaunay/neighbors.hpp"

namespace exidel::python {

namespace {

using delaunay::Location;
using delaunay::LocationKind;

template <class... K>
using LocatorVariant = std::variant<std::unique_ptr<delaunay::Locator<K>>...>;
using AnyLocator = exidel::detail::KernelTypes::apply<LocatorVariant>;

using IndexArray = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>;

class PyLocator {
public:
    PyLocator(py::object points_object, IndexArray triangles, IndexArray halfedges, IndexArray hull,
              bool collinear, const std::string& kernel_name)
        : points_(to_points(points_object, "points")) {
        if (points_.single) throw py::value_error("points: expected shape (n, 2), got (2,)");
        if (triangles.ndim() != 2 || triangles.shape(1) != 3) {
            throw py::value_error("triangles: expected shape (m, 3)");
        }
        const auto copy = [](const IndexArray& a, auto& out, const char* what) {
            const std::int32_t* p = a.data();
            out.resize(static_cast<std::size_t>(a.size()));
            for (std::size_t i = 0; i < out.size(); ++i) {
                using T = typename std::decay_t<decltype(out)>::value_type;
                if constexpr (std::is_unsigned_v<T>) {
                    if (p[i] < 0) throw py::value_error(std::string(what) + ": negative index");
                }
                out[i] = static_cast<typename std::decay_t<decltype(out)>::value_type>(p[i]);
            }
        };
        copy(triangles, tri_.triangles, "triangles");
        copy(halfedges, tri_.halfedges, "halfedges");
        copy(hull, tri_.hull, "hull");
        tri_.collinear = collinear;
        const AnyKernel kernel = to_kernel(kernel_name);
        try {
            std::visit(
                [&](const auto& k) {
                    using K = std::decay_t<decltype(k)>;
                    locator_ = std::make_unique<delaunay::Locator<K>>(points_.span(), tri_, k);
                },
                kernel);
        } catch (const std::invalid_argument& e) {
            throw py::value_error(e.what());
        }
    }

    /// (kind int8, triangle int32, edge int32, vertex int32) arrays, or raises.
    py::tuple locate(py::object queries_object, const std::string& order_name, unsigned threads) {
        const Points queries = to_points(queries_object, "xi");
        delaunay::LocateOptions options;
        if (order_name == "hilbert") {
            options.order = delaunay::LocateOrder::hilbert;
        } else if (order_name == "given") {
            options.order = delaunay::LocateOrder::given;
        } else if (order_name == "jump") {
            options.order = delaunay::LocateOrder::jump;
        } else {
            throw py::value_error("unknown order '" + order_name +
                                  "'; expected hilbert|given|jump");
        }
        if (threads == 0) throw py::value_error("threads must be at least 1");
        options.threads = threads;
        const std::size_t n = queries.rows;
        std::vector<Location> where(n);
        std::optional<delaunay::Failure> failure;
        {
            py::gil_scoped_release release;
            failure = std::visit(
                [&](const auto& l) { return l->locate(queries.span(), where, options); }, locator_);
        }
        if (failure) {
            throw std::runtime_error(std::string(delaunay::to_string(failure->kind)) + ": " +
                                     failure->message);
        }
        std::vector<std::int8_t> kind(n);
        std::vector<std::int32_t> triangle(n), edge(n), vertex(n);
        for (std::size_t i = 0; i < n; ++i) {
            kind[i] = static_cast<std::int8_t>(where[i].kind);
            triangle[i] = where[i].triangle;
            edge[i] = where[i].edge;
            vertex[i] = where[i].vertex == delaunay::no_vertex
                            ? -1
                            : static_cast<std::int32_t>(where[i].vertex);
        }
        return py::make_tuple(to_numpy(std::move(kind)), to_numpy(std::move(triangle)),
                              to_numpy(std::move(edge)), to_numpy(std::move(vertex)));
    }

    /// The nearest vertex (int32) to every query, or raises.
    py::array_t<std::int32_t> nearest(py::object queries_object, unsigned threads) {
        const Points queries = to_points(queries_object, "xi");
        if (threads == 0) throw py::value_error("threads must be at least 1");
        std::vector<std::uint32_t> out(queries.rows);
        std::optional<delaunay::Failure> failure;
        {
            py::gil_scoped_release release;
            failure = std::visit(
                [&](const auto& l) {
                    return l->nearest(queries.span(), out, {.threads = threads});
                },
                locator_);
        }
        if (failure) {
            throw std::runtime_error(std::string(delaunay::to_string(failure->kind)) + ": " +
                                     failure->message);
        }
        std::vector<std::int32_t> result(out.size());
        for (std::size_t i = 0; i < out.size(); ++i) {
            result[i] = out[i] == delaunay::no_vertex ? -1 : static_cast<std::int32_t>(out[i]);
        }
        return to_numpy(std::move(result));
    }

    /// The k nearest points of every query: (q, k) int32, -1 past the distinct points.
    py::array_t<std::int32_t> nearest_k(py::object queries_object, std::size_t k,
                                        unsigned threads) {
        const Points queries = to_points(queries_object, "xi");
        if (threads == 0) throw py::value_error("threads must be at least 1");
        delaunay::NeighborRows rows;
        std::optional<delaunay::Failure> failure;
        {
            py::gil_scoped_release release;
            failure = std::visit(
                [&](const auto& l) {
                    return delaunay::nearest_k(*l, queries.span(), k, rows, {.threads = threads});
                },
                locator_);
        }
        raise(failure);
        py::array_t<std::int32_t> out(
            {static_cast<py::ssize_t>(queries.rows), static_cast<py::ssize_t>(k)});
        std::int32_t* o = out.mutable_data();
        for (std::size_t i = 0; i < queries.rows; ++i) {
            for (std::size_t j = 0; j < k; ++j) {
                const std::size_t at = rows.offsets[i] + j;
                o[i * k + j] =
                    at < rows.offsets[i + 1] ? static_cast<std::int32_t>(rows.vertices[at]) : -1;
            }
        }
        return out;
    }

    /// The points within `radius` of every query: (indptr int64, indices int32).
    py::tuple within_radius(py::object queries_object, double radius, unsigned threads) {
        const Points queries = to_points(queries_object, "xi");
        if (threads == 0) throw py::value_error("threads must be at least 1");
        if (!(radius >= 0) || !std::isfinite(radius)) {
            throw py::value_error("r must be finite and not negative");
        }
        delaunay::NeighborRows rows;
        std::optional<delaunay::Failure> failure;
        {
            py::gil_scoped_release release;
            failure = std::visit(
                [&](const auto& l) {
                    return delaunay::within_radius(*l, queries.span(), radius, rows,
                                                   {.threads = threads});
                },
                locator_);
        }
        raise(failure);
        std::vector<std::int64_t> offsets(rows.offsets.begin(), rows.offsets.end());
        std::vector<std::int32_t> vertices(rows.vertices.begin(), rows.vertices.end());
        return py::make_tuple(to_numpy(std::move(offsets)), to_numpy(std::move(vertices)));
    }

    /// Natural neighbour coordinates, row by row: (offsets int64 (q + 1), vertices int32,
    /// weights float64), or raises.
    py::tuple natural_coordinates(py::object queries_object, bool exact, unsigned threads) {
        const Points queries = to_points(queries_object, "xi");
        const delaunay::NaturalOptions options = natural_options(exact, threads);
        delaunay::NaturalCoordinates c;
        std::optional<delaunay::Failure> failure;
        {
            py::gil_scoped_release release;
            failure = std::visit(
                [&](const auto& l) {
                    return delaunay::natural_coordinates(*l, queries.span(), c, options);
                },
                locator_);
        }
        raise(failure);
        std::vector<std::int64_t> offsets(c.offsets.begin(), c.offsets.end());
        std::vector<std::int32_t> vertices(c.vertices.begin(), c.vertices.end());
        return py::make_tuple(to_numpy(std::move(offsets)), to_numpy(std::move(vertices)),
                              to_numpy(std::move(c.weights)));
    }

    /// Sibson's interpolant of values (n, c) at every query: (q, c) float64, or raises.
    py::array_t<double> natural(
        py::object queries_object,
        py::array_t<double, py::array::c_style | py::array::forcecast> values, double fill,
        bool exact, unsigned threads) {
        const Points queries = to_points(queries_object, "xi");
        if (values.ndim() != 2 || static_cast<std::size_t>(values.shape(0)) != points_.rows) {
            throw py::value_error("values: expected shape (" + std::to_string(points_.rows) +
                                  ", c)");
        }
        const auto columns = static_cast<std::size_t>(values.shape(1));
        py::array_t<double> out(
            {static_cast<py::ssize_t>(queries.rows), static_cast<py::ssize_t>(columns)});
        if (columns == 0) return out;
        const std::span<const double> in(values.data(), static_cast<std::size_t>(values.size()));
        const std::span<double> written(out.mutable_data(), static_cast<std::size_t>(out.size()));
        const delaunay::NaturalOptions options = natural_options(exact, threads);
        std::optional<delaunay::Failure> failure;
        {
            py::gil_scoped_release release;
            failure = std::visit(
                [&](const auto& l) {
                    return delaunay::interpolate_natural(*l, in, columns, queries.span(), written,
                                                         fill, options);
                },
                locator_);
        }
        raise(failure);
        return out;
    }

private:
    static delaunay::NaturalOptions natural_options(bool exact, unsigned threads) {
        if (threads == 0) throw py::value_error("threads must be at least 1");
        delaunay::NaturalOptions options;
        options.locate.threads = threads;
        options.arithmetic =
            exact ? delaunay::NaturalArithmetic::exact : delaunay::NaturalArithmetic::rounded;
        return options;
    }
    static void raise(const std::optional<delaunay::Failure>& failure) {
        if (failure) {
            throw std::runtime_error(std::string(delaunay::to_string(failure->kind)) + ": " +
                                     failure->message);
        }
    }

    Points points_;
    delaunay::Triangulation tri_;
    AnyLocator locator_;
};

}  // namespace

void bind_locate(py::module_& m) {
    py::class_<PyLocator>(m, "Locator",
                          "Exact point location over the arrays of a triangulation "
                          "(delaunay::Locator); exidel.Delaunay.locate uses it.")
        .def(py::init<py::object, IndexArray, IndexArray, IndexArray, bool, const std::string&>(),
             py::arg("points"), py::arg("triangles"), py::arg("halfedges"), py::arg("hull"),
             py::arg("collinear"), py::arg("kernel") = "adaptive")
        .def("locate", &PyLocator::locate, py::arg("xi"), py::arg("order") = "hilbert",
             py::arg("threads") = 1)
        .def("nearest", &PyLocator::nearest, py::arg("xi"), py::arg("threads") = 1)
        .def("nearest_k", &PyLocator::nearest_k, py::arg("xi"), py::arg("k"),
             py::arg("threads") = 1)
        .def("within_radius", &PyLocator::within_radius, py::arg("xi"), py::arg("r"),
             py::arg("threads") = 1)
        .def("natural_coordinates", &PyLocator::natural_coordinates, py::arg("xi"),
             py::arg("exact") = false, py::arg("threads") = 1)
        .def("natural", &PyLocator::natural, py::arg("xi"), py::arg("values"),
             py::arg("fill") = 0.0, py::arg("exact") = false, py::arg("threads") = 1);
    m.attr("location_kinds") = py::make_tuple("inside", "on_edge", "on_vertex", "outside");
}

}  // namespace exidel::python
