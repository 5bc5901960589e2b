#pragma once
// Mandelbulber's primitive shapes (primitive_<type>_<n>_* settings) as graph nodes: spheres,
// boxes, planes and tori, each moved and turned as the file says and joined to the fractal by a
// union, the way Mandelbulber combines them by default. Any other kind, or a setting these do not
// draw (hollow, repeated, another boolean operator), is an error naming the setting and its line.
#include <string>

#include <nlohmann/json.hpp>

#include "common/diagnostics.h"
#include "fract_settings.h"

namespace fg {

// Appends each enabled primitive's nodes to `nodes` and returns the distance output of their union
// with `distance` (`distance` itself when there are none).
std::string import_primitives(const FractSettings& settings, nlohmann::ordered_json& nodes, const std::string& distance,
                              Diagnostics& diag);

}  // namespace fg
