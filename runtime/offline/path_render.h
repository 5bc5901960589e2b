#pragma once
// Offline rendering of a camera path: one image per frame number, in any projection, written with
// a verification record so that re-running a range (--resume) skips what is already done. Each
// frame depends only on its number, so ranges and shards can run anywhere, in any order
// (docs/scale-out.md).
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "camera_path.h"
#include "frame/headless_renderer.h"
#include "frame_range.h"
#include "offline_image.h"

namespace fg {

struct PathRenderSettings {
    Projection projection = Projection::Equirect;
    StereoMode stereo = StereoMode::PerEye;   // perspective and equirect; ODS always marches per pixel
    std::uint32_t width = 512, height = 256;  // output size per eye
    std::uint32_t supersample = 1;            // samples per output pixel along each axis
    std::uint32_t samples = 1;                // jittered frames averaged per frame (perspective)
    double noise = 0.0;                       // adaptive sampling's noise target (SampleBudget)
    std::uint32_t min_samples = 16;
    double detail = 1.0;                      // the hit threshold is 1 / detail of an output pixel
    bool taa = false;                         // temporal anti-aliasing, history from frame to frame
    double taa_upscale = 1.0;                 // with taa: temporal upsampling (marched at 1/this per axis)
    double taa_sharpen = kTaaSharpen;         // with taa: sharpening of slowly moving history
    double aperture = 0.0;                    // depth of field over the samples: the lens's diameter
    double focus = 0.0;                       // ... focused this far ahead (0: at the view's centre, per frame)
    double shutter = 0.0;                     // motion blur over the samples: the open share of a frame
    std::uint32_t cone_levels = 5;
    double ipd_m = 0.064;
    std::map<std::string, double> knobs;
    bool count_evaluations = false;           // SDF evaluations per rendered sample, for cost estimates
    OutputFormat format = OutputFormat::Png;
    ExrCompression compression = ExrCompression::Zip;   // with OutputFormat::Exr
};

// Everything that changes the pixels, as text: part of the job fingerprint in each frame record.
std::string settings_fingerprint(const PathRenderSettings& s);
// DIR/frame_000042.png (.exr for OpenEXR)
std::string frame_image_path(const std::string& dir, int frame, OutputFormat format = OutputFormat::Png);

// A rendered frame before it is encoded: the picture, and with a format that needs them the AOV
// images of each eye.
struct OfflineFrame {
    Rgba8Image picture;
    std::vector<OfflineEye> eyes;
};

class PathRenderer {
public:
    PathRenderer(const vk::Context& ctx, const Pack& pack, CameraPath path, PathRenderSettings settings);

    // The output image of one frame: side-by-side eyes (perspective), one panorama (equirect), or
    // top-bottom panoramas with the left eye on top (ODS).
    Rgba8Image render(int frame) { return render_frame(frame).picture; }
    OfflineFrame render_frame(int frame);
    // The frame's file in the settings' format (safe to call while the next frame renders).
    std::vector<std::uint8_t> encode(const OfflineFrame& frame) const;
    // SDF evaluations per rendered sample (supersamples count) of the last frame, with counting on.
    double last_evaluations_per_sample() const { return last_evaluations_; }
    std::string describe() const { return renderer_->describe(); }
    // The views of the last frame rendered.
    const StereoViews& views() const { return renderer_->views(); }
    const FrameGraph& graph() const { return renderer_->graph(); }
    const CameraPath& path() const { return path_; }
    const PathRenderSettings& settings() const { return settings_; }

private:
    // The renderer's world scale and keyed parameters at a point of the path.
    void move_to(const CameraSample& s);

    CameraPath path_;
    PathRenderSettings settings_;
    std::unique_ptr<HeadlessRenderer> renderer_;
    double last_evaluations_ = 0.0;
};

struct PathRun {
    std::string out_dir;
    FrameRange frames;
    std::string job;          // fingerprint of pack, path and settings, kept in every frame record
    bool resume = false;      // skip frames whose image and record verify
    bool progress = true;     // the progress bar on stderr
};

struct PathRunResult {
    int rendered = 0, skipped = 0;
    double seconds = 0.0;     // wall time of the whole range
    double write_seconds = 0.0;   // encoding and writing, summed over frames (overlaps rendering)
    double evaluations_per_sample = 0.0;   // mean over the rendered frames (with counting on)
};

// Throws std::runtime_error if an image cannot be written.
PathRunResult run_path(PathRenderer& renderer, const PathRun& run);

}  // namespace fg
