// exidel hygiene tests: near-degenerate queries, generated in one library compiled with
// strict floating-point flags (-O2 -ffp-contract=off, no -ffast-math) so that every test
// executable, whatever its own flags, sees bit-identical inputs (docs/background.md section 2:
// inputs made by code compiled with contraction on come out different).
#pragma once

#include <string>
#include <vector>

#include <exidel/predicates/types.hpp>

namespace exidel::hygiene {

struct Orient2dQuery {
    Point2 a, b, c;
};

struct IncircleQuery {
    Point2 a, b, c, d;
};

struct Orient3dQuery {
    Point3 a, b, c, d;
};

struct InsphereQuery {
    Point3 a, b, c, d, e;
};

struct QueryFamily {
    std::string name;
    /// True when the plain double formulas never meet a subnormal input or intermediate on
    /// these queries, so flush-to-zero / denormals-are-zero cannot change their answers.
    bool normal_range;
    std::vector<Orient2dQuery> orient2d;
    std::vector<IncircleQuery> incircle;  // decided with incircle and incircle_cosine
    std::vector<Orient3dQuery> orient3d;
    std::vector<InsphereQuery> insphere;
};

/// Kettner et al.'s three near-collinear configurations (docs/background.md section 4), with p
/// moved over a grid_size x grid_size grid of ulp steps, each with all three choices of pivot.
QueryFamily kettner_family(int grid_size);

/// Four points of an integer circle (radius 65) for many quadruples, scaled by powers of
/// two and translated (exactly or with one rounding), with d moved by -r..r ulps per
/// coordinate; in space, five points of the integer sphere of radius 65 (insphere) and
/// four of a plane through three of them (orient3d), placed alike, the last point moved.
QueryFamily cocircular_family(int ulp_radius);

/// The same shapes near the top of the double range: the formulas' products overflow.
QueryFamily huge_family(int ulp_radius);

/// Subnormal coordinates, and normal coordinates whose products underflow.
QueryFamily underflow_family(int ulp_radius);

/// All of the above, at the sizes the tests use; `scale` 1 is the full size, larger
/// values thin the grids (the environment test runs every kernel five times).
std::vector<QueryFamily> all_families(int scale);

}  // namespace exidel::hygiene
