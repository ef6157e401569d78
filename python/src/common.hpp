// exidel's Python module: what every binding shares. Arrays of points come in as numpy
// float64 arrays of shape (n, 2) (or (2,) for one point), are checked once (shape,
// finiteness, with the first bad row named in the ValueError), and are then read in place
// as exidel::Point2 (two doubles, the layout of a C-contiguous row). Arrays go back to
// Python without a copy: a std::vector is moved into a capsule that numpy owns.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/registry.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::python {

namespace py = pybind11;

static_assert(sizeof(Point2) == 2 * sizeof(double) && alignof(Point2) == alignof(double),
              "a C-contiguous (n, 2) float64 array is read as n Point2");

/// A float64 array, C-contiguous (numpy converts other dtypes and layouts once).
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

static_assert(sizeof(Point3) == 3 * sizeof(double) && alignof(Point3) == alignof(double),
              "a C-contiguous (n, 3) float64 array is read as n Point3");

/// Points of one argument: n rows, or a single point (shape (2,), or (3,) in space) that
/// broadcasts.
struct Points {
    DoubleArray array;              ///< keeps the data alive
    const Point2* data = nullptr;   ///< the rows, for points of the plane
    const Point3* data3 = nullptr;  ///< the rows, for points of space (dimension 3)
    std::size_t rows = 0;
    bool single = false;  ///< shape (2,) or (3,): one point for every row of the other arguments

    std::span<const Point2> span() const noexcept { return {data, rows}; }
};

/// Converts `object` to points of the plane (dimension 2) or of space (3), or throws
/// ValueError naming the argument: the shape is not (n, dimension) or (dimension,), or a
/// coordinate is NaN or infinite (the first such row).
Points to_points(const py::handle& object, const char* argument, int dimension = 2);

/// numpy's broadcasting over point arguments: every (n, 2) argument has the same n, or
/// n = 1 (it repeats). `rows` is that n; `shaped` whether some argument has shape (n, 2),
/// so the result has shape (n,) rather than (). ValueError names a mismatched argument.
struct Broadcast {
    std::size_t rows = 1;
    bool shaped = false;
};
Broadcast broadcast(std::span<const Points> points, std::span<const char* const> names);

/// The kernel a name spells (every name of the CLI: "double", "adaptive", "mpfr:113",
/// ...); ValueError listing the spellings otherwise.
AnyKernel to_kernel(const std::string& name);

/// The algorithm a name spells (exidel.algorithms); ValueError listing them otherwise.
delaunay::Algorithm to_algorithm(const std::string& name);

/// A numpy array owning `values`, with the given shape (the product must be its size).
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
    auto* owned = new std::vector<T>(std::move(values));
    py::capsule free(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return py::array_t<T>(std::move(shape), owned->data(), free);
}
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& values) {
    const auto n = static_cast<py::ssize_t>(values.size());
    return to_numpy(std::move(values), {n});
}

/// Index arrays as numpy int32 (what scipy.spatial uses), without a copy: every index is
/// below 2^31 (the triangulation's own limit, max_points).
py::array_t<std::int32_t> to_int32(std::vector<std::uint32_t>&& values,
                                   std::vector<py::ssize_t> shape);
inline py::array_t<std::int32_t> to_int32(std::vector<std::uint32_t>&& values) {
    const auto n = static_cast<py::ssize_t>(values.size());
    return to_int32(std::move(values), {n});
}

/// A triangulation's arrays into d: triangles (m, 3), halfedges, hull, vertex_of_input,
/// duplicates (int32) and collinear, the keys exidel.Delaunay reads.
void triangulation_arrays(delaunay::Triangulation&& t, py::dict& d);

/// (n, 2) float64 array of points.
py::array_t<double> to_numpy(std::vector<Point2>&& points);

/// A certificate as the dict the Python Certificate reads: ok, total_findings, findings
/// (kind, message, triangle, points, index, other), notes, triangles.
inline py::dict certificate_dict(const delaunay::Certificate& c, py::object notes,
                                 std::size_t triangles) {
    py::list findings;
    for (const delaunay::Finding& f : c.findings) {
        py::dict finding;
        finding["kind"] = std::string(delaunay::to_string(f.kind));
        finding["message"] = f.message;
        finding["triangle"] = f.triangle;
        finding["points"] = py::tuple(py::cast(f.points));
        finding["index"] = f.index;
        finding["other"] = f.other;
        findings.append(finding);
    }
    py::dict d;
    d["ok"] = c.ok();
    d["total_findings"] = c.total_findings;
    d["findings"] = findings;
    d["notes"] = std::move(notes);
    d["triangles"] = triangles;
    return d;
}

void bind_predicates(py::module_& m);
void bind_delaunay(py::module_& m);
void bind_voronoi(py::module_& m);
void bind_locate(py::module_& m);
void bind_mutable(py::module_& m);

}  // namespace exidel::python
