// exidel._core.MutableTriangulation: points inserted and removed one at a time
// (delaunay::MutableTriangulation) for any kernel of the registry. exidel.Delaunay's
// add_points (exidel/_delaunay.py) inserts through it.
#include <pybind11/stl.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "common.hpp"
#include "exidel/delaunay/mutable_triangulation.hpp"

namespace exidel::python {

namespace {

template <class... K>
using MutableVariant = std::variant<std::unique_ptr<delaunay::MutableTriangulation<K>>...>;
using AnyMutable = exidel::detail::KernelTypes::apply<MutableVariant>;

using IdArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

/// A FailureError as the RuntimeError "kind: message" exidel.Delaunay turns into a
/// TriangulationError.
[[noreturn]] void rethrow(const delaunay::FailureError& e) {
    throw std::runtime_error(std::string(delaunay::to_string(e.failure.kind)) + ": " +
                             e.failure.message);
}

class PyMutable {
public:
    PyMutable(py::object points_object, const std::string& kernel_name) {
        const Points points = to_points(points_object, "points");
        if (points.single) throw py::value_error("points: expected shape (n, 2), got (2,)");
        const AnyKernel kernel = to_kernel(kernel_name);
        py::gil_scoped_release release;
        try {
            std::visit(
                [&](const auto& k) {
                    using K = std::decay_t<decltype(k)>;
                    mutable_ =
                        std::make_unique<delaunay::MutableTriangulation<K>>(points.span(), k);
                },
                kernel);
        } catch (const delaunay::FailureError& e) {
            rethrow(e);
        }
    }

    /// Inserts every row; their ids (int32), in order.
    py::array_t<std::int32_t> insert(py::object points_object) {
        const Points points = to_points(points_object, "points");
        std::vector<std::uint32_t> ids(points.rows);
        {
            py::gil_scoped_release release;
            try {
                std::visit(
                    [&](auto& m) {
                        for (std::size_t i = 0; i < points.rows; ++i) {
                            ids[i] = m->insert(points.data[i]);
                        }
                    },
                    mutable_);
            } catch (const delaunay::FailureError& e) {
                rethrow(e);
            }
        }
        return to_int32(std::move(ids));
    }

    /// Removes every id (IndexError for one not live: the ones before it are removed).
    void remove(const IdArray& ids) {
        const std::int64_t* p = ids.data();
        const auto n = static_cast<std::size_t>(ids.size());
        py::gil_scoped_release release;
        try {
            std::visit(
                [&](auto& m) {
                    for (std::size_t i = 0; i < n; ++i) {
                        if (p[i] < 0 || p[i] > INT32_MAX) {
                            throw std::out_of_range("remove: no id " + std::to_string(p[i]));
                        }
                        m->remove(static_cast<std::uint32_t>(p[i]));
                    }
                },
                mutable_);
        } catch (const delaunay::FailureError& e) {
            rethrow(e);
        }
    }

    /// The live points' triangulation: ids, points and triangulate()'s arrays (indices
    /// are positions in ids).
    py::dict snapshot() const {
        delaunay::MutableSnapshot s;
        {
            py::gil_scoped_release release;
            try {
                s = std::visit([](const auto& m) { return m->snapshot(); }, mutable_);
            } catch (const delaunay::FailureError& e) {
                rethrow(e);
            }
        }
        py::dict d;
        d["ids"] = to_int32(std::move(s.ids));
        d["points"] = to_numpy(std::move(s.points));
        triangulation_arrays(std::move(s.triangulation), d);
        return d;
    }

    std::size_t size() const {
        return std::visit([](const auto& m) { return m->size(); }, mutable_);
    }

private:
    AnyMutable mutable_;
};

}  // namespace

void bind_mutable(py::module_& m) {
    py::class_<PyMutable>(m, "MutableTriangulation",
                          "A Delaunay triangulation that points are inserted into and removed "
                          "from one at a time (delaunay::MutableTriangulation).")
        .def(py::init<py::object, const std::string&>(), py::arg("points"),
             py::arg("kernel") = "adaptive")
        .def("insert", &PyMutable::insert, py::arg("points"))
        .def("remove", &PyMutable::remove, py::arg("ids"))
        .def("snapshot", &PyMutable::snapshot)
        .def("__len__", &PyMutable::size);
}

}  // namespace exidel::python
