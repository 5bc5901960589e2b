#pragma once
// A Mandelbulber settings file made a Fractograph graph: the camera, the formula or hybrid with
// its iteration counts and parameters, Julia mode, bailout and iterations, and the step factor.
// Mandelbulber's z axis is up; the graph's y is: a point (x, y, z) there is (x, z, -y) here.
// What changes the shape and cannot be mapped is an error naming the setting and its line; what
// only changes the look (colours, lights, fog, effects) is named in one warning, never dropped
// without a word.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/diagnostics.h"
#include "fract_settings.h"

namespace fg {

std::optional<nlohmann::ordered_json> import_mandelbulber(const FractSettings& settings, const std::string& name,
                                                  Diagnostics& diag);

}  // namespace fg
