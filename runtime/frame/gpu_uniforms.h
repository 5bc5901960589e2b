#pragma once
// The uniform blocks every pass reads, laid out as std140 (runtime/frame/shaders/common.glsl).
// The runtime checks these sizes against the pack's reflection, so a drift fails loudly.
#include <array>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "stereo_rig.h"

namespace fg {

struct GpuView {
    std::array<float, 4> origin, right, up, forward, tan_fov;
};

struct GpuFrame {
    GpuView views[3];                  // left, right, centre
    std::array<std::uint32_t, 4> size; // eye w, h; centre w, h
    std::array<std::uint32_t, 4> info; // frame index, cone levels
    std::array<float, 4> time;         // seconds, world scale, ipd
    std::array<float, 4> pixel;        // half-diagonal tangent, tangent per pixel
};
static_assert(sizeof(GpuFrame) == 3 * 80 + 4 * 16);

struct GpuScene {
    std::array<float, 4> light_dir, light_color, ambient, sss_color, rim_color, albedo, bg_top, bg_bottom, fog, glow,
        bounds, misc, misc2;
};
static_assert(sizeof(GpuScene) == 13 * 16);

GpuFrame make_gpu_frame(const StereoViews& views, std::uint32_t cone_levels, double time, double world_scale,
                        std::uint32_t frame_index);
// From the manifest's scene settings (graph/scene_settings.h).
GpuScene make_gpu_scene(const nlohmann::json& scene);

}  // namespace fg
