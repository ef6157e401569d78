// exidel CLI (internal): exidel triangulate's constrained mode (--constraints, or .poly
// input): points with segments and holes in, the constrained Delaunay triangulation's
// domain out (constrained.cpp).
#pragma once

#include <optional>

#include "common.hpp"
#include "exidel/delaunay/regions.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/io/triangulation.hpp"

namespace exidel::cli {

/// What the constrained mode takes besides the point command's options.
struct ConstrainedSettings {
    /// --fill; by default enclosed for poly input (Triangle's), even-odd otherwise.
    std::optional<delaunay::FillRule> fill;
    io::TriangulationFormat format = io::TriangulationFormat::json;
    delaunay::Options delaunay{};
    bool certify = false;
};

/// The run after the output files exist (`node_output`: the .node beside an .ele): read,
/// triangulate with constraints, classify the regions, optionally certify, write. Returns
/// the exit status.
int run_constrained(const PointCommand& command, const ConstrainedSettings& settings,
                    const AnyKernel& kernel, Clock::time_point start,
                    std::optional<PendingFile>& output, std::optional<PendingFile>& node_output);

/// "even-odd", "non-zero", "enclosed", "all".
std::optional<delaunay::FillRule> fill_rule_from_name(const std::string& name);
/// The name of `rule`, as --fill spells it.
std::string_view fill_rule_name(delaunay::FillRule rule);

}  // namespace exidel::cli
