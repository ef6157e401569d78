// exidel.orient2d, incircle, incircle_cosine, compare_distance, and in space orient3d and
// insphere: one predicate over rows of point arrays. The loop runs here with the GIL released,
// compiled once per kernel type (one std::visit per call, none per row); a (2,) or (1, 2) argument
// broadcasts. The adaptive kernel on arrays that do not broadcast uses the batched predicates.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "common.hpp"
#include "exidel/predicates/batch.hpp"
#include "exidel/predicates/predicate.hpp"

namespace exidel::python {

namespace {

template <Predicate P, class K, std::size_t N>
void evaluate_rows(const K& kernel, const std::array<const Point2*, N>& data,
                   const std::array<std::size_t, N>& stride, std::int8_t* out, std::size_t rows) {
    for (std::size_t i = 0; i < rows; ++i) {
        std::array<Point2, N> q;
        for (std::size_t k = 0; k < N; ++k) q[k] = data[k][i * stride[k]];
        const Sign s = exidel::evaluate(kernel, P, q);
        out[i] = static_cast<std::int8_t>(to_int(s));
    }
}

/// The predicates with a batched form in exidel::batch (batch.hpp).
constexpr bool has_batch(Predicate p) {
    return p == Predicate::orient2d || p == Predicate::incircle ||
           p == Predicate::incircle_cosine || p == Predicate::compare_distance;
}

/// The adaptive kernel on rows without broadcasting: the batched predicates (batch.hpp),
/// whose AVX2 filters take four rows at a time.
template <Predicate P, std::size_t N>
void evaluate_batch(const std::array<const Point2*, N>& data, std::int8_t* out, std::size_t rows) {
    static_assert(sizeof(Sign) == sizeof(std::int8_t));
    std::array<std::span<const Point2>, N> q;
    for (std::size_t k = 0; k < N; ++k) q[k] = {data[k], rows};
    std::vector<Sign> signs(rows);
    if constexpr (P == Predicate::orient2d) {
        batch::orient2d(q[0], q[1], q[2], signs);
    } else if constexpr (P == Predicate::incircle) {
        batch::incircle(q[0], q[1], q[2], q[3], signs);
    } else if constexpr (P == Predicate::incircle_cosine) {
        batch::incircle_cosine(q[0], q[1], q[2], q[3], signs);
    } else {
        static_assert(P == Predicate::compare_distance, "has_batch and evaluate_batch disagree");
        batch::compare_distance(q[0], q[1], q[2], signs);
    }
    if (rows > 0) std::memcpy(out, signs.data(), rows);
}

/// The frame of every vectorised predicate: converts the N point arguments (of the
/// plane, or of space when dimension is 3), broadcasts them, allocates the int8 result,
/// and calls loop(kernel, points, stride, out, rows) once per call, inside one std::visit
/// and with the GIL released.
template <std::size_t N, class Loop>
py::array_t<std::int8_t> over_rows(const std::array<py::object, N>& args,
                                   const std::array<const char*, N>& names,
                                   const std::string& kernel_name, int dimension, Loop loop) {
    const AnyKernel kernel = to_kernel(kernel_name);
    std::array<Points, N> points;
    for (std::size_t k = 0; k < N; ++k) points[k] = to_points(args[k], names[k], dimension);
    const auto [rows, shaped] = broadcast(points, names);
    std::array<std::size_t, N> stride;
    for (std::size_t k = 0; k < N; ++k) stride[k] = points[k].rows == 1 ? 0 : 1;
    std::vector<py::ssize_t> shape;
    if (shaped) shape.push_back(static_cast<py::ssize_t>(rows));
    py::array_t<std::int8_t> result(shape);
    std::int8_t* out = result.mutable_data();
    {
        py::gil_scoped_release release;
        std::visit([&](const auto& k) { loop(k, points, stride, out, rows); }, kernel);
    }
    return result;
}

template <Predicate P, std::size_t N>
py::array_t<std::int8_t> vectorised(const std::array<py::object, N>& args,
                                    const std::array<const char*, N>& names,
                                    const std::string& kernel_name) {
    const auto loop = [](const auto& k, const std::array<Points, N>& points,
                         const std::array<std::size_t, N>& stride, std::int8_t* out,
                         std::size_t rows) {
        std::array<const Point2*, N> data;
        for (std::size_t i = 0; i < N; ++i) data[i] = points[i].data;
        const bool broadcasts =
            rows > 1 && std::find(stride.begin(), stride.end(), 0) != stride.end();
        if constexpr (std::is_same_v<std::decay_t<decltype(k)>, AdaptiveKernel> && has_batch(P)) {
            if (!broadcasts) return evaluate_batch<P>(data, out, rows);
        }
        evaluate_rows<P>(k, data, stride, out, rows);
    };
    return over_rows<N>(args, names, kernel_name, 2, loop);
}

/// orient3d and insphere: the same rows over points of space (no batched path).
template <SpacePredicate P, std::size_t N>
py::array_t<std::int8_t> vectorised(const std::array<py::object, N>& args,
                                    const std::array<const char*, N>& names,
                                    const std::string& kernel_name) {
    const auto loop = [](const auto& k, const std::array<Points, N>& points,
                         const std::array<std::size_t, N>& stride, std::int8_t* out,
                         std::size_t rows) {
        std::array<Point3, N> q;
        for (std::size_t i = 0; i < rows; ++i) {
            for (std::size_t a = 0; a < N; ++a) q[a] = points[a].data3[i * stride[a]];
            out[i] = static_cast<std::int8_t>(to_int(exidel::evaluate(k, P, q)));
        }
    };
    return over_rows<N>(args, names, kernel_name, 3, loop);
}

constexpr const char* kernel_doc =
    " kernel: any spelling of `exidel kernels` (\"double\", \"long-double\", \"adaptive\","
    " \"exact\", \"exact-cpp\", \"mpfr:<bits>\"). Each point argument is an array of shape"
    " (n, 2) or one point (2,), float64 (converted once otherwise); a single point or a"
    " (1, 2) array broadcasts. Returns the signs as int8 (-1, 0, 1), shape (n,), or () when"
    " every argument is one point. A NaN or infinite coordinate raises ValueError naming the"
    " argument and the first bad row.";

constexpr const char* space_doc =
    " kernel: any spelling of `exidel kernels`. Each point argument is an array of shape"
    " (n, 3) or one point (3,), float64; a single point or a (1, 3) array broadcasts. Returns"
    " the signs as int8 (-1, 0, 1), shape (n,), or () when every argument is one point. A NaN"
    " or infinite coordinate raises ValueError naming the argument and the first bad row.";

/// The benchmark's reference: the C++ loop alone over points already in memory (the
/// arguments converted beforehand, no result array allocated per call), in seconds.
double loop_seconds(const std::string& predicate, const py::tuple& args,
                    const std::string& kernel_name) {
    const AnyKernel kernel = to_kernel(kernel_name);
    const auto p = predicate_from_name(predicate);
    if (!p || point_count(*p) != args.size())
        throw py::value_error("predicate and arguments do not match");
    std::vector<Points> points;
    for (std::size_t k = 0; k < args.size(); ++k) points.push_back(to_points(args[k], "argument"));
    const std::size_t rows = points[0].rows;
    for (const Points& q : points) {
        if (q.rows != rows) throw py::value_error("every argument needs the same rows");
    }
    std::vector<std::int8_t> out(rows);
    py::gil_scoped_release release;
    const auto start = std::chrono::steady_clock::now();
    std::visit(
        [&](const auto& k) {
            if (*p == Predicate::orient2d) {
                evaluate_rows<Predicate::orient2d, std::decay_t<decltype(k)>, 3>(
                    k, {points[0].data, points[1].data, points[2].data}, {1, 1, 1}, out.data(),
                    rows);
            } else if (*p == Predicate::incircle) {
                evaluate_rows<Predicate::incircle, std::decay_t<decltype(k)>, 4>(
                    k, {points[0].data, points[1].data, points[2].data, points[3].data},
                    {1, 1, 1, 1}, out.data(), rows);
            } else {
                throw std::invalid_argument("loop_seconds times orient2d and incircle");
            }
        },
        kernel);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// py::object, once per point argument.
template <std::size_t>
using Object = py::object;

/// One Python function per predicate of a list: its name, its points' names as keyword
/// arguments, then `kernel`, and its summary followed by the arguments' documentation.
template <class Which, Which P, std::size_t... I>
void bind_one(py::module_& m, std::index_sequence<I...>, const char* doc) {
    constexpr std::size_t n = sizeof...(I);
    static_assert(n == point_count(P));
    // The names, from "a,b,c": static, since the lambda and py::arg keep pointers to them.
    static const std::array<std::string, n> names = [] {
        std::array<std::string, n> out;
        std::string_view list = predicate_arguments(P);
        for (std::string& name : out) {
            const std::size_t comma = list.find(',');
            name = std::string(list.substr(0, comma));
            list = comma == std::string_view::npos ? std::string_view() : list.substr(comma + 1);
        }
        return out;
    }();
    static const std::array<const char*, n> c_names{names[I].c_str()...};
    m.def(
        std::string(predicate_name(P)).c_str(),
        [](Object<I>... points, const std::string& kernel) {
            return vectorised<P, n>({points...}, c_names, kernel);
        },
        py::arg(c_names[I])..., py::arg("kernel") = "adaptive",
        (std::string(predicate_summary(P)) + doc).c_str());
}

}  // namespace

void bind_predicates(py::module_& m) {
    // Every predicate of the lists (exidel/predicates/predicate.hpp), in list order.
#define EXIDEL_BIND_PREDICATE_(name, points, arguments, summary) \
    bind_one<Predicate, Predicate::name>(m, std::make_index_sequence<points>(), kernel_doc);
    EXIDEL_PREDICATES(EXIDEL_BIND_PREDICATE_)
#undef EXIDEL_BIND_PREDICATE_
#define EXIDEL_BIND_SPACE_PREDICATE_(name, points, arguments, summary)                    \
    bind_one<SpacePredicate, SpacePredicate::name>(m, std::make_index_sequence<points>(), \
                                                   space_doc);
    EXIDEL_SPACE_PREDICATES(EXIDEL_BIND_SPACE_PREDICATE_)
#undef EXIDEL_BIND_SPACE_PREDICATE_
    m.def("_loop_seconds", &loop_seconds, py::arg("predicate"), py::arg("args"),
          py::arg("kernel") = "adaptive",
          "For benchmarks: seconds of the bare C++ loop of orient2d or incircle over the rows.");
}

}  // namespace exidel::python
