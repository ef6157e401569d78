// exidel's Python module, exidel._core: the compiled layer under the `exidel` package.
// Everything here converts and dispatches; the geometry is in exidel::predicates and
// exidel::delaunay, compiled once with their own floating-point flags.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "common.hpp"
#include "exidel/delaunay/algorithms.hpp"
#include "exidel/predicates/build_info.hpp"

namespace exidel::python {

// constrained.cpp: exidel._core.constrained_delaunay and certify_constrained.
void bind_constrained(py::module_& m);

Points to_points(const py::handle& object, const char* argument, int dimension) {
    Points p;
    try {
        p.array = DoubleArray::ensure(object);
    } catch (const py::error_already_set&) {
        p.array = DoubleArray();
    }
    if (!p.array) {
        throw py::value_error(std::string(argument) + ": not convertible to a float64 array");
    }
    const auto d = static_cast<py::ssize_t>(dimension);
    if (p.array.ndim() == 1 && p.array.shape(0) == d) {
        p.single = true;
        p.rows = 1;
    } else if (p.array.ndim() == 2 && p.array.shape(1) == d) {
        p.rows = static_cast<std::size_t>(p.array.shape(0));
    } else {
        std::string shape = "(";
        for (py::ssize_t k = 0; k < p.array.ndim(); ++k) {
            shape += (k ? ", " : "") + std::to_string(p.array.shape(k));
        }
        throw py::value_error(std::string(argument) + ": expected shape (n, " +
                              std::to_string(dimension) + ") or (" + std::to_string(dimension) +
                              ",), got " + shape + (p.array.ndim() == 1 ? ",)" : ")"));
    }
    const double* c = p.array.data();
    for (std::size_t i = 0; i < p.rows; ++i) {
        const double* row = c + i * static_cast<std::size_t>(dimension);
        if (!std::all_of(row, row + dimension, [](double v) { return std::isfinite(v); })) {
            std::string values;
            for (int k = 0; k < dimension; ++k) {
                values += (k ? ", " : "") + py::repr(py::float_(row[k])).cast<std::string>();
            }
            throw py::value_error(std::string(argument) + ": row " + std::to_string(i) +
                                  " is not finite (" + values + ")");
        }
    }
    if (dimension == 3) {
        p.data3 = reinterpret_cast<const Point3*>(c);
    } else {
        p.data = reinterpret_cast<const Point2*>(c);
    }
    return p;
}

Broadcast broadcast(std::span<const Points> points, std::span<const char* const> names) {
    Broadcast b;
    for (std::size_t k = 0; k < points.size(); ++k) {
        if (points[k].single) continue;
        b.shaped = true;
        if (points[k].rows == 1) continue;
        if (b.rows != 1 && points[k].rows != b.rows) {
            throw py::value_error(std::string(names[k]) + ": " + std::to_string(points[k].rows) +
                                  " rows, but an earlier argument has " + std::to_string(b.rows));
        }
        b.rows = points[k].rows;
    }
    return b;
}

AnyKernel to_kernel(const std::string& name) {
    std::string error;
    if (auto kernel = parse_kernel(name, error)) return *std::move(kernel);
    throw py::value_error(error);
}

delaunay::Algorithm to_algorithm(const std::string& name) {
    if (auto a = delaunay::algorithm_from_name(name)) return *a;
    throw py::value_error("unknown algorithm '" + name + "'; expected one of " +
                          delaunay::algorithm_spellings());
}

py::array_t<std::int32_t> to_int32(std::vector<std::uint32_t>&& values,
                                   std::vector<py::ssize_t> shape) {
    auto* owned = new std::vector<std::uint32_t>(std::move(values));
    py::capsule free(owned, [](void* p) { delete static_cast<std::vector<std::uint32_t>*>(p); });
    // Same size and representation for values below 2^31 (C++20: two's complement).
    return py::array_t<std::int32_t>(std::move(shape),
                                     reinterpret_cast<const std::int32_t*>(owned->data()), free);
}

py::array_t<double> to_numpy(std::vector<Point2>&& points) {
    auto* owned = new std::vector<Point2>(std::move(points));
    py::capsule free(owned, [](void* p) { delete static_cast<std::vector<Point2>*>(p); });
    return py::array_t<double>({static_cast<py::ssize_t>(owned->size()), py::ssize_t{2}},
                               reinterpret_cast<const double*>(owned->data()), free);
}

}  // namespace exidel::python

PYBIND11_MODULE(_core, m) {
    namespace py = pybind11;
    using namespace exidel::python;
    m.doc() = "exidel's compiled layer: vectorised predicates, triangulation, certifier, Voronoi";
    m.attr("__version__") = EXIDEL_VERSION_STRING;

    py::list kernels;
    for (std::string_view k : exidel::build_info().kernels) kernels.append(py::str(std::string(k)));
    m.attr("kernel_spellings") = kernels;
    py::list algorithms;
    for (const auto& a : exidel::delaunay::algorithms())
        algorithms.append(py::str(std::string(a.name)));
    m.attr("algorithms") = algorithms;
    m.def(
        "kernel_name", [](const std::string& name) { return exidel::kernel_name(to_kernel(name)); },
        "The canonical name of a kernel spelling (ValueError for an unknown one).");
    m.def("kernel_is_exact",
          [](const std::string& name) { return exidel::kernel_is_exact(to_kernel(name)); });
    m.def("build_info", [] {
        const exidel::BuildInfo& b = exidel::build_info();
        py::dict d;
        d["version"] = std::string(b.version);
        d["commit"] = std::string(b.commit);
        d["compiler"] = std::string(b.compiler);
        d["gmp"] = std::string(b.gmp);
        d["mpfr"] = std::string(b.mpfr);
        d["boost"] = std::string(b.boost);
        d["long_double"] = std::string(b.long_double);
        return d;
    });

    bind_predicates(m);
    bind_delaunay(m);
    bind_voronoi(m);
    bind_locate(m);
    bind_mutable(m);
    bind_constrained(m);
}
