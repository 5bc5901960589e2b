#pragma once
// Runs a FrameGraph on Vulkan: makes a compute pipeline per pack program (with the pack's knob
// values and any overrides as specialization constants), allocates exactly the images the graph
// declares (two of each history image), binds each pass's resources by name, checks every binding
// and push constant against the shader's reflection, and records the graph's batches with a
// barrier between one batch and the next, and timestamps.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frame_graph.h"
#include "gpu_uniforms.h"
#include "pipeline_store.h"
#include "pack/pack_reader.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"
#include "vk/descriptors.h"
#include "vk/image.h"

namespace fg {

namespace vk {
class GpuTimer;
}

// SIMD lanes of a marching pass group, counted with subgroup ballots in the counting frame: every
// iteration of a marching loop adds its subgroup's size to `total` and its lanes that evaluate to `busy`.
struct LaneCount {
    std::uint64_t busy = 0, total = 0;
    double efficiency() const { return total ? static_cast<double>(busy) / static_cast<double>(total) : 0.0; }
};

struct FrameStats {
    std::map<std::string, double> gpu_ms;              // per timer group (or pass), plus "frame"
    std::map<std::string, std::uint64_t> evaluations;  // per counter group (if counting)
    double evaluations_per_pixel = 0.0;                // all groups, per output pixel of both eyes
    std::map<std::string, std::uint64_t> iterations;   // per counter group (if counting): fractal loop iterations
    double iterations_per_pixel = 0.0;                 // all groups, per output pixel of both eyes
    std::map<std::string, LaneCount> lanes;            // per counter group (if counting)
    std::map<std::string, double> reuse_skipped;       // per counter group: the mean share of a ray reuse skipped
};

// Temporal anti-aliasing's history images, shared by the executors of one player that resolve to
// the same size (a governor's levels and scales): one history in memory, handed over on a level
// change (take_history) instead of copied. Each holds the images it was built with.
struct SharedTaaHistory {
    std::map<std::string, std::vector<std::shared_ptr<vk::StorageImage>>> images;
};

class FrameExecutor {
public:
    // Throws std::runtime_error with a clear message for a pack that does not fit this runtime
    // (a missing binding, a knob out of range, a uniform block or push constant of another size,
    // a binding the pass does not declare as the shader uses it).
    // With `pipelines`, pipelines built before for the same SPIR-V and settings are reused; with
    // `taa_history`, the TAA history images of that size and format already there are this
    // executor's too (and those it makes are put there).
    FrameExecutor(const vk::Context& ctx, const Pack& pack, FrameGraph graph, PipelineStore* pipelines = nullptr,
                  SharedTaaHistory* taa_history = nullptr);
    ~FrameExecutor();

    // The frame's uniforms; the executor adds the previous frame's eyes and whether its levels hold
    // for this one (cross-frame reuse).
    void set_frame(const GpuFrame& frame);
    // Adaptive sampling: the eye's full-resolution passes run only on the tiles `sampled` keeps
    // (nullopt: all of them) from the next frame on; the other pixels keep what they held.
    void set_sampled_tiles(int view, std::optional<SampledTiles> sampled);
    // The uniforms of the last frame set, as the shaders see them.
    const GpuFrame& frame() const { return frame_data_; }
    // A changed scene setting (light, background...) forgets the shading history.
    void set_scene(const GpuScene& scene);
    // A parameter may change the distance: the previous frame's levels no longer hold.
    bool set_param(const std::string& name, const Constant& value);
    // The previous frame no longer shows the points this one will (a looping scene wrapped the
    // head): nothing is taken from it (cross-frame reuse, shading history, temporal anti-aliasing).
    void forget_history();
    // A governor level change: this executor's temporal anti-aliasing continues `from`'s history
    // (both resolve to the same output size, whatever size each marches), so the first frame at
    // the new level keeps the picture converged so far. Where both hold the same images
    // (SharedTaaHistory) nothing is copied; otherwise the copy is recorded into the next run().
    // The other histories (reuse, shading) start afresh. False, taking nothing, where the two
    // cannot share one: either without TAA or without a history, or other output sizes.
    bool take_history(const FrameExecutor& from);

    FrameStats run();
    // An image as the last frame left it; "<name>.previous" is a history image's frame before.
    std::vector<std::byte> download(const std::string& image) const;
    // For backends that copy a result on the GPU (an OpenXR swapchain, a window).
    vk::StorageImage& image(const std::string& name) const;
    const FrameGraph& graph() const { return graph_; }
    const PackManifest& manifest() const { return manifest_; }
    std::uint64_t frames_run() const { return frames_run_; }
    // Frames the history holds since it was last forgotten (0: none): temporal anti-aliasing takes
    // its jitter phase from it, so the first frame after a reset is the same for the same view.
    std::uint64_t history_frames() const { return history_valid_ || taa_taken_ ? history_frames_ : 0; }
    // The sub-pixel offset of the eyes' pixel grids for the next frame (StereoSettings::jitter):
    // temporal anti-aliasing's, from history_frames(); none without it.
    glm::dvec2 taa_jitter() const;
    // Still frames after which temporal anti-aliasing has averaged every jitter offset once (each
    // output pixel holds 16 samples: sample_jitter.h taa_phases).
    std::uint32_t refined_frames() const;

private:
    struct Program {
        std::shared_ptr<const KeptPipeline> kept;   // set layout and pipeline
        const ManifestPass* manifest = nullptr;
    };
    static std::string program_key(const FramePass& pass);
    void make_programs(const Pack& pack, PipelineStore* pipelines);
    void check_declarations() const;
    void make_resources(SharedTaaHistory* taa_history);
    void make_descriptor_sets();
    // The image a resource name means in a frame of this parity (history images alternate).
    vk::StorageImage* resolve_image(const std::string& name, std::uint64_t frame) const;
    vk::Buffer* resolve_buffer(const std::string& name) const;
    void record(VkCommandBuffer cmd, vk::GpuTimer* timer);

    const vk::Context& ctx_;
    const PackManifest manifest_;
    FrameGraph graph_;
    std::vector<std::vector<std::size_t>> batches_;
    std::map<std::string, Program> programs_;   // by program_key
    std::vector<const Program*> pass_programs_;  // each pass's, by index
    std::map<std::string, std::vector<std::shared_ptr<vk::StorageImage>>> images_;   // two for history images
    std::vector<std::string> adopted_;   // images from a SharedTaaHistory: their maker cleared them
    std::map<std::string, std::unique_ptr<vk::Buffer>> buffers_;
    std::unique_ptr<vk::Buffer> frame_, scene_, params_, counters_;
    std::unique_ptr<vk::DescriptorPool> pool_;
    std::vector<std::array<VkDescriptorSet, 2>> sets_;   // per pass, per frame parity
    std::vector<std::byte> params_bytes_;
    bool images_initialised_ = false;
    std::uint64_t frames_run_ = 0;
    // History images alternate by frame: frame n writes version (n + parity_) % 2. Taking a
    // shared history aligns parity_ with the giver's, whose last frame wrote the other version.
    std::uint64_t parity_ = 0;
    std::uint64_t parity() const { return frames_run_ + parity_; }
    GpuFrame frame_data_{};
    GpuScene scene_data_{};
    GpuView previous_views_[2]{};   // the eyes of the last frame run
    glm::vec2 previous_jitter_{0.0f};   // and their jitter
    std::uint32_t still_frames_ = 0;    // frames in a row that saw the last frame's view (GpuFrame)
    bool history_valid_ = false;
    // Temporal anti-aliasing's history alone holds, taken from another executor (take_history),
    // whose images the next run copies into this one's before its passes.
    bool taa_taken_ = false;
    std::vector<std::pair<const vk::StorageImage*, vk::StorageImage*>> history_copies_;
    std::uint64_t history_frames_ = 0;
    // The tile lists of the graph's tile buffers, remade only when what places them changes (at a
    // headset's resolution a list has tens of thousands of tiles) and written before the next frame.
    // A list holds the tiles outside the lens until every image holds their pixels (frames_to_fill_
    // frames after it was placed: two where history images alternate), then leaves them out.
    struct TileList {
        std::array<float, 8> placed_by{};   // eye size, lens centre and radii, fovea radius and blend
        std::uint64_t placed_at = 0;        // the frame it was placed for
        bool placed = false;
        bool outside_left = false;          // the tiles outside the lens are left out
        std::uint64_t sampled_version = 0;  // the sampled tiles it holds (sampled_version_)
        std::vector<std::uint32_t> tiles;
        bool written = false;
    };
    std::uint64_t frames_to_fill_ = 1;
    void update_tile_lists();
    std::map<std::string, TileList> tile_lists_;   // by buffer name
    std::array<std::optional<SampledTiles>, 3> sampled_tiles_;   // by view
    std::uint64_t sampled_version_ = 0;            // counts set_sampled_tiles
    std::unique_ptr<vk::Buffer> no_tiles_;         // bound where a pass dispatches no tiles
    std::unique_ptr<vk::Buffer> environment_;      // environment_light.h, where the pack has one
};

// The specialization constants of a pack with overrides applied: the manifest's values, then
// `knobs` by name (range-checked), then count_evaluations.
vk::SpecializationValues specialization_for(const PackManifest& m, const ManifestPass& pass,
                                            const std::map<std::string, double>& knobs, bool count_evaluations);

}  // namespace fg
