#pragma once
// Graph parameters keyed in a camera path, against the pack that plays it: parameters are uniforms,
// so a path can move them frame by frame without recompiling anything.
#include <vector>

#include "camera_path.h"
#include "common/diagnostics.h"
#include "pack/manifest.h"

namespace fg {

// Every keyed parameter exists in the pack, has its size, and lies in its range; errors name the
// keyframe field (/keyframes/2/params/power) and list the pack's parameters for an unknown name.
bool check_path_params(const CameraPath& path, const PackManifest& manifest, Diagnostics& diag);

// The value to set: clamped into the parameter's range, since a smooth curve through in-range
// keys may overshoot between them.
Constant keyed_param_value(const ManifestParam& param, const std::vector<double>& value);

}  // namespace fg
