#pragma once
// `fgplay render`: headless stereo frames to images, with GPU times and evaluation counts.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "frame/frame_settings.h"
#include "offline/offline_image.h"

namespace fg::fgplay {

struct RenderOptions {
    std::string pack;
    std::string out = "out";
    std::uint32_t width = 512, height = 512;
    double ipd_m = 0.064;
    std::optional<std::array<double, 6>> camera;   // position, target
    StereoMode stereo = StereoMode::PerEye;
    std::uint32_t cone_levels = 5;
    int frames = 1;
    // Offline rendering of a camera path (fgplay_render_path.cpp).
    std::string path;                // camera path JSON (docs/camera-path.md)
    std::string frame_range;         // --frames with --path: A:B
    std::string shard;               // I/N
    Projection projection = Projection::Perspective;
    std::uint32_t supersample = 1;
    std::uint32_t samples = 1;       // jittered frames averaged per picture (offline/jittered_samples.h)
    double noise = 0.0;              // adaptive sampling: a pixel's noise target (0: every pixel every sample)
    std::uint32_t min_samples = 16;  // ... taken before a pixel may stop
    double detail = 1.0;             // the hit threshold and normal taps: 1 / detail of an output pixel
    bool taa = false;                // temporal anti-aliasing (with --frames or --path: history carried)
    double taa_upscale = 1.0;        // temporal upsampling: marched at 1/this of the size per axis
    double taa_sharpen = kTaaSharpen;   // with taa: sharpening of slowly moving history, 0 = none
    double aperture = 0.0;           // depth of field: the lens's diameter in scene units (0: pinhole)
    double focus = 0.0;              // ... focused this far ahead (0: at what the view's centre sees)
    double shutter = 0.0;            // with --path: motion blur, the open share of each frame's interval
    OutputFormat format = OutputFormat::Png;
    ExrCompression compression = ExrCompression::Zip;
    bool resume = false;
    bool progress = true;
    double time = 0.0;
    bool describe = false;
    bool depth = false;
    bool count = false;              // --count: SDF evaluations and lanes per pass (5-10 % of the GPU time)
    bool time_passes = false;        // GPU time of each pass, counting off (as the benchmark times)
    bool validation = false;
    std::string device;
    std::map<std::string, double> knobs;
    bool lens_mask = false;
    double foveation = -1.0;   // < 0: as the scene says
    bool whole_dispatch = false;   // no tile lists: what the tiles save
};

int render(const RenderOptions& o);
int render_path(const RenderOptions& o);

}  // namespace fg::fgplay
