#pragma once
// Headless rendering: a pack, a head pose and a time in, both eyes' images, depths, GPU times and
// evaluation counts out. Deterministic: the same inputs give the same bytes.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frame_executor.h"
#include "image_output.h"
#include "stereo_rig.h"

namespace fg {

struct RenderedFrame {
    Rgba8Image left, right;            // a mono projection (equirect) fills only left

    std::vector<float> depth_left, depth_right;
    // With FrameSettings::aovs: each eye's AOV images as downloaded, in aov_images() order.
    std::vector<std::vector<std::byte>> aovs_left, aovs_right;
    // With FrameSettings::hdr: each eye's tone map input, rgba per pixel (alpha: the fade's share kept).
    std::vector<float> hdr_left, hdr_right;
    FrameStats stats;
};

class HeadlessRenderer {
public:
    // With `pipelines`, pipelines built before for the same SPIR-V and settings are reused; with
    // `taa_history`, renderers of one size hold one TAA history (FrameExecutor::take_history).
    HeadlessRenderer(const vk::Context& ctx, const Pack& pack, const FrameSettings& frame, const StereoSettings& stereo,
                     PipelineStore* pipelines = nullptr, SharedTaaHistory* taa_history = nullptr);

    // The camera the scene starts with (scene.camera), symmetric field of view.
    HeadPose scene_camera() const;
    Fov scene_fov() const;
    const StereoViews& views() const { return views_; }
    std::string describe() const { return executor_->graph().describe(); }

    RenderedFrame render(const HeadPose& head, double time, std::uint32_t frame_index = 0);
    // The same frame with nothing read back, only its stats: a GPU kept busy with frames back to back
    // holds its clock, as under a headset's load, where readbacks between frames would let it fall.
    FrameStats run(const HeadPose& head, double time, std::uint32_t frame_index = 0);
    // The sub-pixel offset of both eyes' pixel grids from the next frame on (StereoSettings::jitter).
    void set_jitter(glm::dvec2 pixels) { stereo_.jitter = pixels; }
    // Adaptive sampling: from the next frame on, each eye marches and shades only the tiles its
    // `sampled` keeps (nullptr: all); its other pixels keep what they held. Needs tile dispatch.
    void set_sampled_tiles(const SampledTiles* left, const SampledTiles* right) {
        executor_->set_sampled_tiles(FG_VIEW_LEFT, left ? std::optional(*left) : std::nullopt);
        executor_->set_sampled_tiles(FG_VIEW_RIGHT, right ? std::optional(*right) : std::nullopt);
    }
    // Depth of field for jittered samples (render_samples): a thin lens of `aperture` (its diameter,
    // scene units; 0: a pinhole) focused `focus` scene units ahead.
    void set_depth_of_field(double aperture, double focus) {
        aperture_ = aperture;
        focus_ = focus;
    }
    double aperture() const { return aperture_; }
    double focus() const { return focus_; }
    // From the next frame on, both eyes look from `offset` (scene units) off their lens's centre
    // (StereoSettings::lens), focused at focus().
    void set_lens(glm::dvec2 offset) {
        stereo_.lens = offset;
        stereo_.focus = offset == glm::dvec2(0.0) ? 0.0 : focus_;
    }
    // Area lights from the next frame on: the sample's index (each pixel's point on the light is
    // its own scrambling of one sequence, fg_light_sample), or none for a single frame
    // (light.soft_shadow's cone-angle penumbra).
    void set_light_sample(std::optional<std::uint32_t> index) { light_sample_ = index; }
    // Output pixels per marched pixel from the next frame on (FrameSettings::detail_scale: a picture
    // shown at another size than it is rendered); a change forgets the frames before.
    void set_detail_scale(double scale);
    // Scene units per metre from the next frame on (a camera path zooms): the IPD follows it.
    void set_world_scale(double world_scale);
    FrameExecutor& executor() { return *executor_; }
    const FrameGraph& graph() const { return executor_->graph(); }

private:
    const vk::Context& ctx_;
    const Pack& pack_;
    StereoViews make_views(const HeadPose& head) const;

    FrameSettings frame_;
    double detail_scale_ = 1.0;
    StereoSettings stereo_;
    double aperture_ = 0.0, focus_ = 0.0;
    std::optional<std::uint32_t> light_sample_;
    StereoViews views_;
    std::unique_ptr<FrameExecutor> executor_;
};

}  // namespace fg
