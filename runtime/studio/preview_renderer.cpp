#include "studio/preview_renderer.h"

#include <chrono>

#include <algorithm>

#include "frame/image_output.h"
#include "frame/sample_jitter.h"

namespace fg::studio {

FrameSettings preview_frame_settings(std::uint32_t eye_size, bool taa) {
    FrameSettings frame;
    frame.taa = taa;
    frame.width = frame.height = eye_size;
    frame.stereo = StereoMode::PerEye;
    frame.count_evaluations = true;
    return frame;
}

PreviewRenderer::PreviewRenderer(const vk::Context& ctx, std::uint32_t eye_size) : ctx_(ctx), size_(eye_size) {}

std::unique_ptr<PreviewScene> prepare_scene(const vk::Context& ctx, Pack pack, std::uint64_t revision,
                                            std::uint32_t eye_size, bool with_probe, PipelineStore* pipelines) {
    auto scene = std::make_unique<PreviewScene>();
    scene->pack = std::make_unique<Pack>(std::move(pack));
    StereoSettings stereo;
    stereo.world_scale = scene->pack->manifest.scene.world_scale;
    scene->renderer = std::make_unique<HeadlessRenderer>(ctx, *scene->pack, preview_frame_settings(eye_size, true), stereo,
                                                         pipelines);
    if (with_probe) scene->probe = std::make_unique<CollisionProbe>(ctx, *scene->pack, pipelines);
    scene->revision = revision;
    return scene;
}

PreviewFrame render_scene(PreviewScene& scene, const PreviewRequest& request, std::uint32_t frame_index,
                          RenderedFrame& rendered) {
    auto start = std::chrono::steady_clock::now();
    HeadlessRenderer& renderer = *scene.renderer;
    // A parameter set again forgets the frames before, even at the same value: a still view would
    // never refine.
    for (const auto& [name, value] : request.params) {
        auto it = scene.applied.find(name);
        if (it != scene.applied.end() && it->second == value) continue;
        if (renderer.executor().set_param(name, value)) scene.applied[name] = value;
    }
    // The page's pixels are the output's: the detail of the picture it shows, at any render size.
    if (request.display_width > 0.0) renderer.set_detail_scale(renderer.views().left.width / request.display_width);
    HeadPose head = renderer.scene_camera();
    if (request.position && request.target && *request.position != *request.target)
        head = look_at(*request.position, *request.target);
    rendered = renderer.render(head, 0.0, frame_index);
    PreviewFrame out;
    Rgba8Image image = request.side_by_side ? side_by_side(rendered.left, rendered.right) : rendered.left;
    out.png = encode_png(image);
    out.width = image.width;
    out.height = image.height;
    if (auto it = rendered.stats.gpu_ms.find("frame"); it != rendered.stats.gpu_ms.end()) out.gpu_ms = it->second;
    out.evaluations_per_pixel = rendered.stats.evaluations_per_pixel;
    out.revision = scene.revision;
    if (renderer.graph().taa) out.samples = std::min(renderer.executor().frame().still_frames + 1, kRefinedFrames);
    out.cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

void PreviewRenderer::show(std::unique_ptr<PreviewScene> scene) {
    std::unique_ptr<PreviewScene> old;
    {
        std::lock_guard lock(mutex_);
        old = std::move(scene_);
        scene_ = std::move(scene);
        last_ = {};
    }
    // `old` is released here, outside the lock; its frames are finished (render waits for them).
}

std::optional<PreviewFrame> PreviewRenderer::render(const PreviewRequest& request) {
    std::lock_guard lock(mutex_);
    if (!scene_) return std::nullopt;
    return render_scene(*scene_, request, static_cast<std::uint32_t>(frames_++), last_);
}

std::optional<ProbeHit> PreviewRenderer::probe(std::uint32_t x, std::uint32_t y) {
    std::lock_guard lock(mutex_);
    if (!scene_ || last_.depth_left.empty() || x >= size_ || y >= size_) return std::nullopt;
    const View& view = scene_->renderer->views().left;
    ProbeHit hit;
    hit.depth = last_.depth_left[static_cast<std::size_t>(y) * size_ + x];
    if (hit.depth < 0.0) return hit;
    glm::dvec3 dir = view.ray((x + 0.5) / size_, (y + 0.5) / size_);
    hit.hit = true;
    hit.point = view.origin + dir * hit.depth;
    std::uint64_t ticket = scene_->probe->submit({hit.point});
    if (ticket == 0) return std::nullopt;
    if (auto result = scene_->probe->wait(ticket); result && !result->samples.empty())
        hit.distance = result->samples.front().distance;
    return hit;
}

std::uint64_t PreviewRenderer::frames() const {
    std::lock_guard lock(mutex_);
    return frames_;
}

std::optional<std::pair<glm::dvec3, glm::dvec3>> PreviewRenderer::scene_camera() const {
    std::lock_guard lock(mutex_);
    if (!scene_) return std::nullopt;
    const auto& camera = scene_->pack->manifest.scene.camera;
    return std::make_pair(camera.position, camera.target);
}

}  // namespace fg::studio
