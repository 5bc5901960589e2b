#pragma once
// Filling the uniform blocks every pass reads (frame/shaders/gpu_interface.h, shared with GLSL).
// The runtime checks their sizes against the pack's reflection, so a drift fails loudly.
#include <cstdint>

#include "frame/shaders/gpu_interface.h"
#include "frame_settings.h"
#include "graph/scene_settings.h"
#include "stereo_rig.h"

namespace fg {

// `settings` as the frame graph resolved them (lens mask, foveation, projection).
GpuFrame make_gpu_frame(const StereoViews& views, const FrameSettings& settings, double time, double world_scale,
                        std::uint32_t frame_index);
// From the manifest's scene settings, decoded when the pack was read.
GpuScene make_gpu_scene(const SceneSettings& s);

}  // namespace fg
