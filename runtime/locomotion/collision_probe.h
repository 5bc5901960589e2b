#pragma once
// The asynchronous collision probe: distance and normal at a few points (the head, and where the
// head is predicted to be), computed by the pack's probe program on the GPU and read back a frame
// or two later without waiting. Several probes are in flight at once, each in its own slot.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "frame/pipeline_store.h"
#include "pack/pack_reader.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"
#include "vk/descriptors.h"

namespace fg {

struct ProbeSample {
    glm::dvec3 point{0.0};
    double distance = 0.0;          // the scene's distance estimate: the ball of this radius is empty
    glm::dvec3 normal{0.0, 1.0, 0.0};
};

struct ProbeResult {
    std::uint64_t ticket = 0;       // which submit() it answers
    std::vector<ProbeSample> samples;
};

class CollisionProbe {
public:
    static constexpr std::size_t kSlots = 3;
    static constexpr std::size_t kMaxPoints = 8;

    // With `pipelines`, the probe's pipeline is the one built before for the same SPIR-V.
    CollisionProbe(const vk::Context& ctx, const Pack& pack, PipelineStore* pipelines = nullptr);
    ~CollisionProbe();
    CollisionProbe(const CollisionProbe&) = delete;
    CollisionProbe& operator=(const CollisionProbe&) = delete;

    // Starts a probe at up to kMaxPoints points; returns its ticket, or 0 when every slot is
    // still busy (the caller simply tries again next frame).
    std::uint64_t submit(const std::vector<glm::dvec3>& points);
    // The newest finished probe not yet returned, without blocking.
    std::optional<ProbeResult> poll();
    // Blocks until the probe with this ticket is done (tests, and shutting down).
    std::optional<ProbeResult> wait(std::uint64_t ticket);

private:
    struct Slot {
        std::unique_ptr<vk::Buffer> points, results;
        // Packs of precision "double" evaluate at the frame's anchor + point: each probe gets its
        // own anchor (the first point), so the points travel as small float offsets.
        std::unique_ptr<vk::Buffer> frame;
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkFence fence = VK_NULL_HANDLE;
        VkDescriptorSet set = VK_NULL_HANDLE;
        std::uint64_t ticket = 0;   // 0 = free
        std::vector<glm::dvec3> asked;
    };
    ProbeResult collect(Slot& slot);

    const vk::Context& ctx_;
    std::shared_ptr<const KeptPipeline> kept_;   // set layout and pipeline
    std::unique_ptr<vk::DescriptorPool> pool_;
    std::unique_ptr<vk::Buffer> scene_, params_;
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    std::array<Slot, kSlots> slots_;
    double normal_step_ = 1e-4;
    bool camera_relative_ = false;
    std::uint64_t next_ticket_ = 1;
};

}  // namespace fg
