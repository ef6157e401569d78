// exidel CLI (internal): `exidel certify --constraints CONSTRAINTS TRIANGULATION`, the exact
// constrained certifier on files (constrained_certify.cpp; the help text in certify.cpp).
#pragma once

#include <optional>
#include <string>

#include "exidel/delaunay/regions.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation_input.hpp"
#include "options.hpp"

namespace exidel::cli {

struct ConstrainedCertifySettings {
    std::optional<io::PointFormat> input_format;  ///< of CONSTRAINTS
    std::optional<io::ProducedFormat> format;     ///< of TRIANGULATION: json, ele or off
    /// The domain the file must be: --fill's rule (by default triangulate's: enclosed for
    /// .poly, even-odd otherwise), or with `any_domain` any union of regions.
    std::optional<delaunay::FillRule> fill;
    bool any_domain = false;
    bool tolerate_crossings = false;
    bool all = false, json = false, strict = false, quiet = false;
};

/// Reads, rebuilds, completes, certifies and reports; returns the exit status.
int run_constrained_certify(const std::string& constraints_path, const std::string& tri_path,
                            const ConstrainedCertifySettings& settings, const CommandLine& cli);

}  // namespace exidel::cli
