#pragma once
// How a frame is rendered: what the user or the benchmark chooses, as opposed to what the pack
// (the scene) decides.
#include <cstdint>
#include <map>
#include <string>

#include "projection.h"

namespace fg {

enum class StereoMode {
    Reproject,   // conemarch the centre eye, reproject to each eye, fix-up march (the seeds' method)
    PerEye,      // conemarch each eye on its own
    Naive,       // plain sphere tracing of each eye at full resolution: the baseline
};

// TAA's default sharpening (FrameSettings::taa_sharpen): slow orbits and walks of the gallery
// Julia and Kleinian at 256^2 keep 0.97-1.07 of the reference's detail against 0.87-0.92 without,
// for 0.1-1.1 dB of PSNR and no change of SSIM (docs/runtime.md).
inline constexpr double kTaaSharpen = 0.2;

const char* stereo_mode_name(StereoMode m);
bool parse_stereo_mode(const std::string& s, StereoMode& out);

struct FrameSettings {
    std::uint32_t width = 256, height = 256;   // per eye
    StereoMode stereo = StereoMode::PerEye;
    Projection projection = Projection::Perspective;   // panoramas: offline renders
    std::uint32_t cone_levels = 5;              // conemarch levels including full resolution
    bool count_evaluations = false;             // SDF evaluations per pass (a specialization constant)
    bool time_each_pass = false;                // GPU time per pass (its label), not per pass group
    // The AOV pass: the picture's terms as images for a compositor (aov.* per eye; OpenEXR output).
    bool aovs = false;
    // The shade pass also keeps each eye's colour before the tone map (hdr.<eye>): accumulated
    // samples average it and tone-map the mean once, so that a stochastic term (an area light, the
    // environment) converges to the picture of its mean, not to the mean of its tone-mapped
    // pictures. Every pixel is shaded (no foveation); not with temporal anti-aliasing.
    bool hdr = false;
    // Fewer pixels: the lens mask skips what the headset's lens hides; fixed foveation marches and
    // shades one pixel in four beyond the fovea. Foveation < 0 takes the scene's foveation block
    // (off without one), 0 is off, > 0 is the fovea radius in half image heights.
    bool lens_mask = false;
    // Frames may carry a lens the user did not ask for: an OpenXR runtime's visibility mask, which
    // the player puts into each frame's views (so the passes keep their lens tests).
    bool headset_lens = false;
    bool frames_may_hold_lens() const { return lens_mask || headset_lens; }
    double foveation = -1.0;
    double foveation_blend = 0.15;             // band over which fovea and periphery blend (same unit)
    // Each pass of an eye dispatches only the 8x8 tiles that hold its pixels (the fovea's, the
    // periphery's, those the lens shows), not its whole image (the same frames; off only to measure
    // or test what the tiles save).
    bool tile_dispatch = true;
    // Temporal anti-aliasing: each frame's rays go through a jittered pixel grid, and a resolve pass
    // blends them into a history per eye (taa_pass.cpp). Static float scenes in perspective only.
    bool taa = false;
    // Temporal upsampling: with taa, the taa pass resolves each eye to this size (0: width x height,
    // the marched size) from frames marched at 1/taa_upscale_factor of it per axis (set_taa_upscale).
    std::uint32_t output_width = 0, output_height = 0;
    double taa_upscale_factor = 1.0;
    bool taa_upscales() const { return taa && output_width && taa_upscale_factor > 1.0; }
    std::uint32_t shown_width() const { return taa_upscales() ? output_width : width; }
    std::uint32_t shown_height() const { return taa_upscales() ? output_height : height; }
    double taa_upscale() const { return taa_upscales() ? taa_upscale_factor : 1.0; }
    // The shown picture sharpens history that moves less than a pixel a frame, in proportion to how
    // far between texels it was fetched: the blur each frame's resampling adds (taa.comp).
    double taa_sharpen = kTaaSharpen;
    // Output pixels are this many marched pixels wide (the supersampling factor; below 1 where an
    // image is shown larger than it was marched): the hit threshold and normal taps follow them.
    double detail_scale = 1.0;
    std::map<std::string, double> knobs;        // specialization constant overrides by manifest name
    // Persistent lanes: invocations each persistent dispatch launches at least (0: as many as the
    // device runs at once; persistent_groups.h). For tests and sweeps.
    std::uint64_t persistent_invocations = 0;
    // Set from the pack, not by the user: a pack of precision "double" gets its view origins
    // relative to the camera (gpu_uniforms.h).
    bool camera_relative = false;
};

// Temporal upsampling by `factor` (1 = none): `f`'s width x height become the output size, marched
// at 1/factor of it per axis, with the detail of the output pixel.
void set_taa_upscale(FrameSettings& f, double factor);

}  // namespace fg
