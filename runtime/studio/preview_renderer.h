#pragma once
// The studio's live preview: one Vulkan context for the whole session, the pack of the newest good
// compile with its pipelines already built (a scene), frames rendered on request with the page's
// camera and parameter values. Parameters are uniforms: moving a slider renders again, it never
// recompiles. A failed compile leaves the scene that plays.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/value_type.h"
#include "frame/headless_renderer.h"
#include "frame/pipeline_store.h"
#include "locomotion/collision_probe.h"
#include "pack/pack_reader.h"
#include "vk/context.h"

namespace fg::studio {

// A pack ready to render: built on the compile thread, shown when complete.
struct PreviewScene {
    std::unique_ptr<Pack> pack;
    std::unique_ptr<HeadlessRenderer> renderer;
    std::unique_ptr<CollisionProbe> probe;
    std::uint64_t revision = 0;
    std::map<std::string, Constant> applied;   // parameter values set so far: only a change is set again
};

struct PreviewRequest {
    std::optional<glm::dvec3> position, target;     // the scene's camera when absent
    bool side_by_side = false;
    std::map<std::string, Constant> params;         // by name; unknown names are ignored
    double display_width = 0.0;                     // device pixels the page shows an eye across (0: as rendered)
};

struct PreviewFrame {
    std::vector<std::uint8_t> png;
    std::uint32_t width = 0, height = 0;
    double gpu_ms = -1.0;            // -1: the device has no timestamps
    double cpu_ms = 0.0;             // render and read back, wall clock
    double evaluations_per_pixel = 0.0;
    std::uint64_t revision = 0;
    std::uint32_t samples = 1;       // samples per pixel the picture holds (a still view refines to 16)
};

struct ProbeHit {
    bool hit = false;
    glm::dvec3 point{0.0};
    double depth = 0.0;              // along the ray from the eye
    double distance = 0.0;           // the scene's distance estimate at the point (the probe)
};

// Pipelines (and the probe, if asked) for a pack, on any thread; throws std::runtime_error if the
// pack does not fit this runtime.
std::unique_ptr<PreviewScene> prepare_scene(const vk::Context& ctx, Pack pack, std::uint64_t revision,
                                            std::uint32_t eye_size, bool with_probe,
                                            PipelineStore* pipelines = nullptr);

// One frame of a scene as the page asked for it; `rendered` keeps the eyes and depths.
PreviewFrame render_scene(PreviewScene& scene, const PreviewRequest& request, std::uint32_t frame_index,
                          RenderedFrame& rendered);

class PreviewRenderer {
public:
    PreviewRenderer(const vk::Context& ctx, std::uint32_t eye_size);

    // The pipelines of passes an edit did not change are the previous scene's.
    std::unique_ptr<PreviewScene> prepare(Pack pack, std::uint64_t revision) {
        return prepare_scene(ctx_, std::move(pack), revision, size_, true, &pipelines_);
    }
    void show(std::unique_ptr<PreviewScene> scene);

    std::optional<PreviewFrame> render(const PreviewRequest& request);
    // The surface under pixel (x, y) of the left eye of the last frame.
    std::optional<ProbeHit> probe(std::uint32_t x, std::uint32_t y);

    std::uint32_t eye_size() const { return size_; }
    // Pipelines built for the scenes so far (the others were reused from the scene before).
    std::uint64_t pipelines_built() const { return pipelines_.built(); }
    std::uint64_t frames() const;
    // The scene's start camera, for the page's orbit.
    std::optional<std::pair<glm::dvec3, glm::dvec3>> scene_camera() const;

private:
    const vk::Context& ctx_;
    std::uint32_t size_;
    PipelineStore pipelines_;
    mutable std::mutex mutex_;
    std::unique_ptr<PreviewScene> scene_;
    RenderedFrame last_;
    std::uint64_t frames_ = 0;
};

// The frame settings every studio view renders with (evaluations counted for the page's figure);
// the live preview adds temporal anti-aliasing, so a still view refines.
FrameSettings preview_frame_settings(std::uint32_t eye_size, bool taa = false);

}  // namespace fg::studio
