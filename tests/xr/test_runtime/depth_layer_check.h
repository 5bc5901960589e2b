#pragma once
// XR_KHR_composition_layer_depth as a compositor receives it: each projection view must chain an
// XrCompositionLayerDepthInfoKHR (when the app enabled the extension, and only then) whose depth
// swapchain matches the colour one, whose range makes sense, and whose values stay inside it; the
// sky is maxDepth, and some pixels are nearer. The last frame's depth is dumped with the layer's
// poses and fields of view ($FG_XR_TEST_DUMP/xr_depth.json and xr_depth_<eye>.f32) so that a judge
// with the scene (tests/xr/depth_layer_judge.cpp) can compare it with the CPU twin.
#include <functional>
#include <string>

#include "runtime_objects.h"

namespace fgxrt {

bool is_depth_format(VkFormat f);
const char* depth_format_name(VkFormat f);

void check_depth_layer(Session& s, const XrCompositionLayerProjection& layer, int frame,
                       const std::function<void(const std::string&)>& fail);

}  // namespace fgxrt
