// exidel: the plain floating kernel, instantiated for double and long double.
#include "exidel/predicates/floating.hpp"

#include <type_traits>

#include "formulas.hpp"
#include "exidel/predicates/internal/fp_hygiene.hpp"

namespace exidel {

namespace {
template <class T>
constexpr auto lift_to = [](double v) { return static_cast<T>(v); };
}

template <class T>
std::string FloatingKernel<T>::name() {
    return std::is_same_v<T, double> ? "double" : "long-double";
}

template <class T>
Sign FloatingKernel<T>::orient2d(Point2 a, Point2 b, Point2 c) noexcept {
    return detail::orient2d_formula<T>(a, b, c, lift_to<T>);
}

template <class T>
Sign FloatingKernel<T>::incircle(Point2 a, Point2 b, Point2 c, Point2 d) noexcept {
    return detail::incircle_formula<T>(a, b, c, d, lift_to<T>);
}

template <class T>
Sign FloatingKernel<T>::incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) noexcept {
    return detail::incircle_cosine_formula<T>(a, b, c, d, lift_to<T>);
}

template <class T>
Sign FloatingKernel<T>::compare_distance(Point2 c, Point2 p, Point2 q) noexcept {
    return detail::compare_distance_formula<T>(c, p, q, lift_to<T>);
}

template <class T>
Sign FloatingKernel<T>::orient3d(Point3 a, Point3 b, Point3 c, Point3 d) noexcept {
    return detail::orient3d_formula<T>(a, b, c, d, lift_to<T>);
}

template <class T>
Sign FloatingKernel<T>::insphere(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e) noexcept {
    return detail::insphere_formula<T>(a, b, c, d, e, lift_to<T>);
}

template struct FloatingKernel<double>;
template struct FloatingKernel<long double>;

}  // namespace exidel
