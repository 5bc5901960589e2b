#pragma once
// The uniform blocks every pass reads, laid out as std140 (runtime/frame/shaders/common.glsl).
// The runtime checks these sizes against the pack's reflection, so a drift fails loudly.
#include <array>
#include <cstdint>

#include "frame_settings.h"
#include "graph/scene_settings.h"
#include "stereo_rig.h"

namespace fg {

struct GpuView {
    std::array<float, 4> origin, right, up, forward, tan_fov;
    std::array<float, 4> lens;         // lens mask ellipse: centre uv, radii uv (0: off)
};

struct GpuFrame {
    GpuView views[3];                  // left, right, centre
    std::array<std::uint32_t, 4> size; // eye w, h; centre w, h
    std::array<std::uint32_t, 4> info; // frame index, cone levels, projection
    std::array<float, 4> time;         // seconds, world scale, ipd
    std::array<float, 4> pixel;        // half-diagonal tangent, tangent per pixel
    std::array<float, 4> foveation;    // fovea radius (0: off), blend band
    // The centre eye in double as hi + lo floats; with settings.camera_relative (packs of precision
    // "double") every view origin is relative to it.
    std::array<float, 4> anchor_hi, anchor_lo;
};
static_assert(sizeof(GpuFrame) == 3 * 96 + 7 * 16);

struct GpuScene {
    std::array<float, 4> light_dir, light_color, ambient, sss_color, rim_color, albedo, bg_top, bg_bottom, fog, glow,
        bounds, misc, misc2;
    std::array<float, 4> bounds_lo;    // what float loses of the bounds' centre (double packs add it)
};
static_assert(sizeof(GpuScene) == 14 * 16);

// `settings` as the frame graph resolved them (lens mask, foveation).
GpuFrame make_gpu_frame(const StereoViews& views, const FrameSettings& settings, double time, double world_scale,
                        std::uint32_t frame_index);
// From the manifest's scene settings.
GpuScene make_gpu_scene(const SceneSettings& s);

}  // namespace fg
