#include "xr/depth_layer.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "spirv/glsl_compiler.h"
#include "vk/commands.h"
#include "xr/eye_swapchain.h"
#include "xr/xr_error.h"

namespace fg::xr {

namespace {

// One invocation per 32-bit word of the copy's source buffer: one pixel of D32_SFLOAT, two of D16_UNORM.
constexpr const char* kDepthShader = R"(#version 460
layout(local_size_x = 64) in;
layout(set = 0, binding = 0, r32f) uniform readonly image2D fg_depth;   // distance along the ray, < 0: sky
layout(set = 0, binding = 1, std430) writeonly buffer FgWindowDepth { uint words[]; };
layout(push_constant) uniform FgDepthPush {
    vec4 tan_fov;    // left, right, down, up
    vec4 range;      // near (m), far (m), scene units per metre, minDepth
    vec4 range2;     // maxDepth, the largest hit depth (just short of maxDepth), unused, unused
    uvec4 size;      // output width, height; source width, height
    uint bits16;
} pc;

float window_depth(uint index)
{
    // The colour blit filters linearly when the render size differs from the swapchain's: the depth
    // takes the nearest hit among the render pixels that blit blends, so a pixel whose colour shows
    // any of the fractal is not sky. At equal sizes that is the one render pixel.
    uvec2 out_px = uvec2(index % pc.size.x, index / pc.size.x);
    vec2 p = (vec2(out_px) + 0.5) * vec2(pc.size.zw) / vec2(pc.size.xy) - 0.5;
    ivec2 base = ivec2(floor(p));
    vec2 f = p - vec2(base);
    float t = -1.0;
    ivec2 src = clamp(base, ivec2(0), ivec2(pc.size.zw) - 1);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            float weight = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
            if (weight <= 1e-4) continue;
            ivec2 s = clamp(base + ivec2(i, j), ivec2(0), ivec2(pc.size.zw) - 1);
            float ts = imageLoad(fg_depth, s).x;
            if (ts >= 0.0 && (t < 0.0 || ts < t)) {
                t = ts;
                src = s;
            }
        }
    if (t < 0.0) return pc.range2.x;   // the sky: exactly maxDepth
    vec2 uv = (vec2(src) + 0.5) / vec2(pc.size.zw);
    float tx = mix(pc.tan_fov.x, pc.tan_fov.y, uv.x), ty = mix(pc.tan_fov.w, pc.tan_fov.z, uv.y);
    // Distance along the ray in scene units -> distance along the forward axis in metres.
    float z = t * inversesqrt(1.0 + tx * tx + ty * ty) / pc.range.z;
    float n = pc.range.x, far = pc.range.y;
    float d = clamp(far / (far - n) * (1.0 - n / max(z, n)), 0.0, 1.0);
    return min(mix(pc.range.w, pc.range2.x, d), pc.range2.y);
}

void main()
{
    uint word = gl_GlobalInvocationID.x;
    uint pixels = pc.size.x * pc.size.y;
    if (pc.bits16 == 0u) {
        if (word < pixels) words[word] = floatBitsToUint(window_depth(word));
        return;
    }
    uint first = 2u * word;
    if (first >= pixels) return;
    uint lo = uint(round(window_depth(first) * 65535.0));
    uint hi = first + 1u < pixels ? uint(round(window_depth(first + 1u) * 65535.0)) : 0u;
    words[word] = lo | (hi << 16);
}
)";

VkImageMemoryBarrier2 depth_barrier(VkImage image, VkImageLayout from, VkImageLayout to, vk::Access src, vk::Access dst) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = src.stage;
    b.srcAccessMask = src.access;
    b.dstStageMask = dst.stage;
    b.dstAccessMask = dst.access;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    return b;
}

void barrier(VkCommandBuffer cmd, const VkImageMemoryBarrier2& b) {
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

}  // namespace

struct DepthPush {
    float tan_fov[4];
    float range[4];
    float range2[4];
    std::uint32_t size[4];
    std::uint32_t bits16;
};

std::optional<std::int64_t> choose_depth_format(const std::vector<std::int64_t>& offered) {
    for (VkFormat f : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM})
        if (std::find(offered.begin(), offered.end(), static_cast<std::int64_t>(f)) != offered.end()) return f;
    return std::nullopt;
}

DepthSwapchain::DepthSwapchain(const vk::Context& ctx, XrSession session, std::int64_t format, std::uint32_t width,
                               std::uint32_t height)
    : format_(format), width_(width), height_(height) {
    swapchain_ = create_vulkan_swapchain(session, XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT,
                                         format, width, height, images_, "xrCreateSwapchain (depth)");

    Diagnostics diag;
    auto spirv = compile_glsl("xr depth layer", kDepthShader, SourceMap{}, diag);
    if (!spirv) throw std::runtime_error("the depth layer's shader does not compile:\n" + diag.format());
    const bool bits16 = format == VK_FORMAT_D16_UNORM;
    const VkDeviceSize bytes = static_cast<VkDeviceSize>(width) * height * (bits16 ? 2 : 4);
    staging_ = std::make_unique<vk::Buffer>(ctx, (bytes + 3) / 4 * 4,
                                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                            vk::MemoryKind::DeviceLocal);
    layout_ = std::make_unique<vk::DescriptorSetLayout>(
        ctx, std::vector<vk::DescriptorBinding>{{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    pool_ = std::make_unique<vk::DescriptorPool>(ctx, *layout_, 1);
    set_ = pool_->allocate(*layout_);
    vk::write_storage_buffer(ctx, set_, 1, *staging_);
    pipeline_ = std::make_unique<vk::ComputePipeline>(ctx, *spirv, std::vector<VkDescriptorSetLayout>{layout_->handle()},
                                                      static_cast<std::uint32_t>(sizeof(DepthPush)));
}

DepthSwapchain::~DepthSwapchain() {
    if (swapchain_) xrDestroySwapchain(swapchain_);
}

void DepthSwapchain::describe(XrCompositionLayerDepthInfoKHR& info, const DepthProjection& p) const {
    info.type = XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR;
    info.subImage.swapchain = swapchain_;
    info.subImage.imageRect = {{0, 0}, {static_cast<std::int32_t>(width_), static_cast<std::int32_t>(height_)}};
    info.subImage.imageArrayIndex = 0;
    info.minDepth = p.min_depth;
    info.maxDepth = p.max_depth;
    info.nearZ = p.near_m;
    info.farZ = p.far_m;
}

DepthPush DepthSwapchain::conversion(const vk::Context& ctx, vk::StorageImage& depth, const Fov& fov,
                                     double scene_units_per_metre, const DepthProjection& p) {
    // Every frame: the frame graph's images change with the governor's sizes (the last frame's
    // copy has finished, so the set is free to update).
    vk::write_storage_image(ctx, set_, 0, depth);
    const bool bits16 = format_ == VK_FORMAT_D16_UNORM;
    DepthPush push{};
    const float tans[4] = {static_cast<float>(fov.left), static_cast<float>(fov.right), static_cast<float>(fov.down),
                           static_cast<float>(fov.up)};
    std::copy(std::begin(tans), std::end(tans), push.tan_fov);
    // Hits stay one step short of maxDepth, so maxDepth means the sky and nothing else.
    const float last_hit = bits16 ? p.max_depth - 1.0f / 65535.0f : std::nextafter(p.max_depth, 0.0f);
    push.range[0] = p.near_m;
    push.range[1] = p.far_m;
    push.range[2] = static_cast<float>(scene_units_per_metre);
    push.range[3] = p.min_depth;
    push.range2[0] = p.max_depth;
    push.range2[1] = last_hit;
    push.size[0] = width_;
    push.size[1] = height_;
    push.size[2] = depth.extent().width;
    push.size[3] = depth.extent().height;
    push.bits16 = bits16 ? 1u : 0u;
    return push;
}

std::uint32_t DepthSwapchain::words() const {
    const std::uint32_t pixels = width_ * height_;
    return format_ == VK_FORMAT_D16_UNORM ? (pixels + 1) / 2 : pixels;
}

void DepthSwapchain::prepare(const vk::Context& ctx, vk::StorageImage& depth, const Fov& fov, double scene_units_per_metre,
                             const DepthProjection& p) {
    const DepthPush push = conversion(ctx, depth, fov, scene_units_per_metre, p);
    vk::OneShot::run(ctx, [&](VkCommandBuffer cmd) {
        depth.transition(cmd, VK_IMAGE_LAYOUT_GENERAL, vk::access::compute_write, vk::access::compute_read);
        pipeline_->dispatch(cmd, set_, {vk::groups_for(words(), 64)}, vk::bytes_of(push));
        depth.transition(cmd, VK_IMAGE_LAYOUT_GENERAL, vk::access::compute_read, vk::access::compute_read_write);
    });
}

void DepthSwapchain::present(const vk::Context& ctx, vk::StorageImage& depth, const Fov& fov, double scene_units_per_metre,
                             const DepthProjection& p) {
    std::uint32_t index = 0;
    XrSwapchainImageAcquireInfo acquire{XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
    check(xrAcquireSwapchainImage(swapchain_, &acquire, &index), "xrAcquireSwapchainImage (depth)");
    XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
    wait.timeout = XR_INFINITE_DURATION;
    check(xrWaitSwapchainImage(swapchain_, &wait), "xrWaitSwapchainImage (depth)");
    if (index >= images_.size())
        throw XrError(XR_ERROR_RUNTIME_FAILURE, fmt::format("the runtime acquired depth swapchain image {} of {}", index, images_.size()));
    const DepthPush push = conversion(ctx, depth, fov, scene_units_per_metre, p);

    VkImage target = images_[index];
    vk::OneShot::run(ctx, [&](VkCommandBuffer cmd) {
        depth.transition(cmd, VK_IMAGE_LAYOUT_GENERAL, vk::access::compute_write, vk::access::compute_read);
        pipeline_->dispatch(cmd, set_, {vk::groups_for(words(), 64)}, vk::bytes_of(push));
        vk::compute_to_transfer_barrier(cmd);
        // The runtime hands depth images over in DEPTH_STENCIL_ATTACHMENT_OPTIMAL and wants them back in it.
        const vk::Access attachment{VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
        barrier(cmd, depth_barrier(target, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                   attachment, vk::access::transfer_write));
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
        region.imageExtent = {width_, height_, 1};
        vkCmdCopyBufferToImage(cmd, staging_->handle(), target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        barrier(cmd, depth_barrier(target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                   vk::access::transfer_write, attachment));
        // The next frame's passes write the depth image again.
        depth.transition(cmd, VK_IMAGE_LAYOUT_GENERAL, vk::access::compute_read, vk::access::compute_read_write);
    });
    XrSwapchainImageReleaseInfo release{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
    check(xrReleaseSwapchainImage(swapchain_, &release), "xrReleaseSwapchainImage (depth)");
}

}  // namespace fg::xr
