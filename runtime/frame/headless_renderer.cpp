#include "headless_renderer.h"

#include <cstring>

#include "aov_images.h"

namespace fg {

namespace {
std::vector<float> floats(const std::vector<std::byte>& bytes) {
    std::vector<float> out(bytes.size() / 4);
    std::memcpy(out.data(), bytes.data(), out.size() * 4);
    return out;
}
}  // namespace

HeadlessRenderer::HeadlessRenderer(const vk::Context& ctx, const Pack& pack, const FrameSettings& frame,
                                   const StereoSettings& stereo, PipelineStore* pipelines, SharedTaaHistory* taa_history)
    : ctx_(ctx), pack_(pack), frame_(frame), detail_scale_(frame.detail_scale), stereo_(stereo) {
    set_marched_size(stereo_, frame);
    // The frame graph's sizes depend only on the fields of view, not on the pose.
    views_ = make_views(scene_camera());
    executor_ = std::make_unique<FrameExecutor>(
        ctx_, pack_, FrameGraph::build(pack_.manifest, frame_, views_.centre.width, views_.centre.height), pipelines, taa_history);
}

HeadPose HeadlessRenderer::scene_camera() const {
    const auto& camera = pack_.manifest.scene.camera;
    return look_at(camera.position, camera.target, camera.up);
}

Fov HeadlessRenderer::scene_fov() const {
    return Fov::symmetric(pack_.manifest.scene.camera.fov_deg, static_cast<double>(frame_.width) / frame_.height);
}

StereoViews HeadlessRenderer::make_views(const HeadPose& head) const {
    if (frame_.projection != Projection::Perspective) return make_panorama_views(head, stereo_);
    return make_stereo_views(head, scene_fov(), scene_fov(), stereo_);
}

void HeadlessRenderer::set_world_scale(double world_scale) { stereo_.world_scale = world_scale; }

void HeadlessRenderer::set_detail_scale(double scale) {
    if (scale == detail_scale_) return;
    detail_scale_ = scale;
    executor_->forget_history();
}

FrameStats HeadlessRenderer::run(const HeadPose& head, double time, std::uint32_t frame_index) {
    // Without temporal anti-aliasing the jitter stays as set_jitter left it (jittered samples).
    if (executor_->graph().taa) stereo_.jitter = executor_->taa_jitter();
    views_ = make_views(head);
    FrameSettings settings = executor_->graph().settings;
    settings.detail_scale = detail_scale_;
    GpuFrame gpu = make_gpu_frame(views_, settings, time, stereo_.world_scale, frame_index);
    if (light_sample_) gpu.area_light = {static_cast<float>(*light_sample_), 0.0f, 1.0f, 0.0f};
    executor_->set_frame(gpu);
    return executor_->run();
}

RenderedFrame HeadlessRenderer::render(const HeadPose& head, double time, std::uint32_t frame_index) {
    RenderedFrame out;
    out.stats = run(head, time, frame_index);
    bool mono = is_mono(frame_.projection);
    std::string left = mono ? "centre" : "left";
    const FrameGraph& g = executor_->graph();
    out.left = rgba8_from_bytes(executor_->download("final." + left), g.output_width, g.output_height);
    out.depth_left = floats(executor_->download("depth." + left));
    auto download_aovs = [&](const std::string& eye, std::vector<std::vector<std::byte>>& into) {
        if (!frame_.aovs) return;
        // An image the scene has no term for is left empty (aov_image_needed).
        for (const AovImage& a : aov_images())
            into.push_back(graph().find_image(aov_image_name(a, eye)) ? executor_->download(aov_image_name(a, eye))
                                                                       : std::vector<std::byte>());
    };
    download_aovs(left, out.aovs_left);
    if (graph().find_image("hdr." + left)) out.hdr_left = floats(executor_->download("hdr." + left));
    if (!mono) {
        out.right = rgba8_from_bytes(executor_->download("final.right"), g.output_width, g.output_height);
        out.depth_right = floats(executor_->download("depth.right"));
        download_aovs("right", out.aovs_right);
        if (graph().find_image("hdr.right")) out.hdr_right = floats(executor_->download("hdr.right"));
    }
    return out;
}

}  // namespace fg
