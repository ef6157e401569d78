// exidel I/O (internal): the GeoJSON point reader (format: exidel/io/points.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "exidel/io/points.hpp"

namespace exidel::io::detail {

/// The points of a GeoJSON text; z from `z_property` of each feature's properties when
/// given, else from the positions' third coordinates (when every position has one).
PointFile parse_geojson_points(std::string_view data, const std::optional<std::string>& z_property);

}  // namespace exidel::io::detail
