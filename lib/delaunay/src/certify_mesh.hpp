// exidel: the certifier's checks shared between certify() and certify_constrained(), inside
// lib/delaunay's sources (never in an installed header).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::delaunay::detail {

/// The points a finding names, from indices of any integer types.
struct FindingPoints {
    std::vector<std::int64_t> v;
    FindingPoints() = default;
    template <class... I>
    FindingPoints(I... i) : v{static_cast<std::int64_t>(i)...} {}
};

struct MeshCertificate {
    Certificate certificate;
    /// For every point, the smallest index with the same coordinates; empty when a point
    /// is not finite (the checks then stop at non_finite_input).
    std::vector<std::uint32_t> first;
};

/// certify()'s checks 1-7, except that check 7 (Delaunay) skips the interior edges listed
/// in `exempt`: undirected edges as (u, v) with u < v, sorted and without repeats. With no
/// exempt edges this is certify().
MeshCertificate certify_mesh(std::span<const Point2> points, const Triangulation& tri,
                             std::span<const std::array<std::uint32_t, 2>> exempt,
                             std::size_t max_findings);

}  // namespace exidel::delaunay::detail
