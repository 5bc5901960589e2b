#pragma once
// Reads a lat-long OpenEXR file as the scene's environment image (pack/environment_image.h).
#include <optional>
#include <string>

#include "pack/environment_image.h"

namespace fg {

// Nullopt and `error` set (OpenEXR's reason, or the first texel that is not a finite radiance)
// when the file cannot serve. Negative values are clamped to 0; alpha is ignored.
std::optional<EnvironmentImage> read_environment_exr(const std::string& path, std::string& error);

}  // namespace fg
