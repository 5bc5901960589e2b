#pragma once
// XR_KHR_composition_layer_depth: each eye's depth, submitted beside its colour so the compositor
// can reproject with it (positional timewarp) and mix layers. The frame graph is compute-only
// and its depth.<eye> image holds the distance along each ray in scene units (FG_MISS for the
// sky); a small compute pass turns that into the window depth of the projection declared in
// XrCompositionLayerDepthInfoKHR (metres = scene units / world scale, z along the eye's forward
// axis, depth = far / (far - near) * (1 - near / z), the sky exactly maxDepth) and writes a buffer,
// which is copied into the depth aspect of the acquired swapchain image: depth formats are
// transfer destinations everywhere, storage images almost nowhere.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "frame/stereo_rig.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"
#include "vk/descriptors.h"
#include "vk/image.h"
#include "xr/xr_instance.h"

namespace fg::xr {

// D32_SFLOAT first (no quantisation of the march's depth), then D16_UNORM; none of these: no depth layer.
std::optional<std::int64_t> choose_depth_format(const std::vector<std::int64_t>& offered);

// What the window depth means: declared in XrCompositionLayerDepthInfoKHR.
struct DepthProjection {
    float near_m = 0.05f;      // metres
    float far_m = 100.0f;      // the march's far limit in metres: nothing nearer is sky
    float min_depth = 0.0f, max_depth = 1.0f;
};

struct DepthPush;   // the conversion pass's push constants

// One eye's depth swapchain, the same size as its colour swapchain.
class DepthSwapchain {
public:
    DepthSwapchain(const vk::Context& ctx, XrSession session, std::int64_t format, std::uint32_t width, std::uint32_t height);
    ~DepthSwapchain();
    DepthSwapchain(const DepthSwapchain&) = delete;
    DepthSwapchain& operator=(const DepthSwapchain&) = delete;

    // Acquire, wait, convert `depth` (depth.<eye>, GENERAL, rendered through `fov` at
    // `scene_units_per_metre`; when sizes differ, the nearest hit among the render pixels the
    // colour blit blends) into the image, release.
    void present(const vk::Context& ctx, vk::StorageImage& depth, const Fov& fov, double scene_units_per_metre,
                 const DepthProjection& projection);

    // The conversion alone, into the staging buffer: what a later present of a depth image of this
    // size needs is made now (lavapipe compiles the pass again for an image size it has not run),
    // not in a frame.
    void prepare(const vk::Context& ctx, vk::StorageImage& depth, const Fov& fov, double scene_units_per_metre,
                 const DepthProjection& projection);

    // Fills the chained struct for a projection view (its `next` is left to the caller).
    void describe(XrCompositionLayerDepthInfoKHR& info, const DepthProjection& projection) const;

    XrSwapchain handle() const { return swapchain_; }
    std::int64_t format() const { return format_; }

private:
    // Binds `depth` to the conversion pass and returns its push constants.
    DepthPush conversion(const vk::Context& ctx, vk::StorageImage& depth, const Fov& fov, double scene_units_per_metre,
                         const DepthProjection& p);
    std::uint32_t words() const;   // of the staging buffer

    XrSwapchain swapchain_ = XR_NULL_HANDLE;
    std::vector<VkImage> images_;
    std::int64_t format_ = 0;
    std::uint32_t width_ = 0, height_ = 0;
    std::unique_ptr<vk::Buffer> staging_;
    std::unique_ptr<vk::DescriptorSetLayout> layout_;
    std::unique_ptr<vk::DescriptorPool> pool_;
    std::unique_ptr<vk::ComputePipeline> pipeline_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace fg::xr
