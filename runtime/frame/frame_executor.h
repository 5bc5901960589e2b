#pragma once
// Runs a FrameGraph on Vulkan: makes a compute pipeline per pack program (with the pack's knob
// values and any overrides as specialization constants), allocates exactly the images the graph
// declares, binds each pass's resources by name, and records the passes with barriers and
// timestamps.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "frame_graph.h"
#include "gpu_uniforms.h"
#include "pack/pack_reader.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"
#include "vk/descriptors.h"
#include "vk/image.h"

namespace fg {

// SIMD lanes of a marching pass group, counted with subgroup ballots in the counting frame: every
// iteration of a marching loop adds its subgroup's size to `total` and its lanes that evaluate to `busy`.
struct LaneCount {
    std::uint64_t busy = 0, total = 0;
    double efficiency() const { return total ? static_cast<double>(busy) / static_cast<double>(total) : 0.0; }
};

struct FrameStats {
    std::map<std::string, double> gpu_ms;              // per timer group, plus "frame"
    std::map<std::string, std::uint64_t> evaluations;  // per counter group (if counting)
    double evaluations_per_pixel = 0.0;                // all groups, per output pixel of both eyes
    std::map<std::string, LaneCount> lanes;            // per counter group (if counting)
};

class FrameExecutor {
public:
    // Throws std::runtime_error with a clear message for a pack that does not fit this runtime
    // (a missing binding, a knob out of range, a uniform block of another size).
    FrameExecutor(const vk::Context& ctx, const Pack& pack, FrameGraph graph);
    ~FrameExecutor();

    void set_frame(const GpuFrame& frame);
    void set_scene(const GpuScene& scene);
    bool set_param(const std::string& name, const Constant& value);

    FrameStats run();
    std::vector<std::byte> download(const std::string& image) const;
    // For backends that copy a result on the GPU (an OpenXR swapchain, a window).
    vk::StorageImage& image(const std::string& name) const;
    const FrameGraph& graph() const { return graph_; }

private:
    struct Program {
        std::unique_ptr<vk::DescriptorSetLayout> layout;
        std::unique_ptr<vk::ComputePipeline> pipeline;
        const ManifestPass* manifest = nullptr;
    };
    void make_programs(const Pack& pack);
    void make_resources();
    void make_descriptor_sets();

    const vk::Context& ctx_;
    const PackManifest manifest_;
    FrameGraph graph_;
    std::map<std::string, Program> programs_;
    std::map<std::string, std::unique_ptr<vk::StorageImage>> images_;
    std::map<std::string, std::unique_ptr<vk::Buffer>> buffers_;
    std::unique_ptr<vk::Buffer> frame_, scene_, params_, counters_;
    std::unique_ptr<vk::DescriptorPool> pool_;
    std::vector<VkDescriptorSet> sets_;                 // one per pass
    std::vector<std::byte> params_bytes_;
    bool images_initialised_ = false;
};

// The specialization constants of a pack with overrides applied: the manifest's values, then
// `knobs` by name (range-checked), then count_evaluations.
vk::SpecializationValues specialization_for(const PackManifest& m, const ManifestPass& pass,
                                            const std::map<std::string, double>& knobs, bool count_evaluations);

}  // namespace fg
