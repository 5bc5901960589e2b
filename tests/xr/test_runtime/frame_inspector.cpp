#include "frame_inspector.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBIW_ASSERT(x)
#include <stb/stb_image_write.h>
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

namespace fgxrt {

namespace {

void vk_check(VkResult r, const char* call) {
    if (r != VK_SUCCESS) throw std::runtime_error(std::string(call) + " failed: " + std::to_string(r));
}

VkImageMemoryBarrier layout_barrier(VkImage image, VkImageLayout from, VkImageLayout to, VkAccessFlags src, VkAccessFlags dst) {
    VkImageMemoryBarrier b{};
    b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    b.srcAccessMask = src;
    b.dstAccessMask = dst;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    return b;
}

double luma(const EyeImage& img, std::size_t i) {
    const std::uint8_t* p = &img.rgba[4 * i];
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

}  // namespace

FrameVerdict judge_stereo_pair(const EyeImage& left, const EyeImage& right) {
    FrameVerdict v;
    const EyeImage* eyes[2] = {&left, &right};
    for (int e = 0; e < 2; ++e) {
        const EyeImage& img = *eyes[e];
        std::size_t n = static_cast<std::size_t>(img.width) * img.height;
        if (img.rgba.size() != 4 * n || n == 0) {
            v.problems.push_back(std::string(e ? "right" : "left") + " eye: no pixels read back");
            continue;
        }
        std::uint8_t lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
        double sum = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            for (int c = 0; c < 3; ++c) {
                lo[c] = std::min(lo[c], img.rgba[4 * i + c]);
                hi[c] = std::max(hi[c], img.rgba[4 * i + c]);
            }
            sum += luma(img, i);
        }
        v.mean_luma[e] = sum / static_cast<double>(n);
        int spread = 0;
        for (int c = 0; c < 3; ++c) spread = std::max(spread, hi[c] - lo[c]);
        if (spread <= 4) v.problems.push_back(std::string(e ? "right" : "left") + " eye is blank (one flat colour)");
    }
    if (left.width == right.width && left.height == right.height && left.rgba.size() == right.rgba.size() &&
        !left.rgba.empty()) {
        std::size_t n = left.rgba.size() / 4, differ = 0;
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(left.rgba[4 * i + c]) - int(right.rgba[4 * i + c])) > 2) {
                    ++differ;
                    break;
                }
        v.eyes_differ_fraction = static_cast<double>(differ) / static_cast<double>(n);
        if (v.eyes_differ_fraction < 0.01) v.problems.push_back("both eyes show the same image");
    }
    return v;
}

FrameInspector::FrameInspector(VkPhysicalDevice physical, VkDevice device, std::uint32_t queue_family,
                               std::uint32_t queue_index)
    : physical_(physical), device_(device) {
    vkGetDeviceQueue(device_, queue_family, queue_index, &queue_);
    VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pi.queueFamilyIndex = queue_family;
    vk_check(vkCreateCommandPool(device_, &pi, nullptr, &pool_), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    vk_check(vkAllocateCommandBuffers(device_, &ai, &cmd_), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    vk_check(vkCreateFence(device_, &fi, nullptr, &fence_), "vkCreateFence");
}

FrameInspector::~FrameInspector() {
    vkDeviceWaitIdle(device_);
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
    vkDestroyFence(device_, fence_, nullptr);
    vkDestroyCommandPool(device_, pool_, nullptr);
}

void FrameInspector::ensure_buffer(VkDeviceSize size) {
    if (size <= buffer_size_) return;
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
    VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bi.size = size;
    bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    vk_check(vkCreateBuffer(device_, &bi, nullptr, &buffer_), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, buffer_, &req);
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(physical_, &props);
    const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    std::uint32_t type = UINT32_MAX;
    for (std::uint32_t i = 0; i < props.memoryTypeCount && type == UINT32_MAX; ++i)
        if ((req.memoryTypeBits & (1u << i)) && (props.memoryTypes[i].propertyFlags & want) == want) type = i;
    if (type == UINT32_MAX) throw std::runtime_error("no host-visible coherent memory");
    VkMemoryAllocateInfo mi{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mi.allocationSize = req.size;
    mi.memoryTypeIndex = type;
    vk_check(vkAllocateMemory(device_, &mi, nullptr, &memory_), "vkAllocateMemory");
    vk_check(vkBindBufferMemory(device_, buffer_, memory_, 0), "vkBindBufferMemory");
    vk_check(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
    buffer_size_ = size;
}

void FrameInspector::submit(const std::vector<VkImageMemoryBarrier>& before, VkImage copy_from, std::uint32_t width,
                            std::uint32_t height, const std::vector<VkImageMemoryBarrier>& after, VkImageAspectFlags aspect) {
    vk_check(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk_check(vkBeginCommandBuffer(cmd_, &bi), "vkBeginCommandBuffer");
    vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr,
                         static_cast<std::uint32_t>(before.size()), before.data());
    if (copy_from) {
        VkBufferImageCopy region{};
        region.imageSubresource = {aspect, 0, 0, 1};
        region.imageExtent = {width, height, 1};
        vkCmdCopyImageToBuffer(cmd_, copy_from, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer_, 1, &region);
        VkBufferMemoryBarrier host{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        host.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        host.buffer = buffer_;
        host.size = VK_WHOLE_SIZE;
        vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &host, 0,
                             nullptr);
    }
    if (!after.empty())
        vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             aspect == VK_IMAGE_ASPECT_DEPTH_BIT ? VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT
                                                                 : VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                             0, 0,
                             nullptr, 0, nullptr, static_cast<std::uint32_t>(after.size()), after.data());
    vk_check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd_;
    vk_check(vkQueueSubmit(queue_, 1, &si, fence_), "vkQueueSubmit");
    vk_check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    vk_check(vkResetFences(device_, 1, &fence_), "vkResetFences");
}

void FrameInspector::prepare(VkImage image) {
    // A layout change only: later users synchronise with their own barriers.
    submit({layout_barrier(image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 0, 0)},
           VK_NULL_HANDLE, 0, 0, {});
}

EyeImage FrameInspector::read(VkImage image, VkFormat format, std::uint32_t width, std::uint32_t height) {
    EyeImage out;
    out.width = width;
    out.height = height;
    out.format = format;
    VkDeviceSize size = static_cast<VkDeviceSize>(width) * height * texel_bytes(format);
    ensure_buffer(size);
    const VkAccessFlags app_writes = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    submit({layout_barrier(image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, app_writes,
                           VK_ACCESS_TRANSFER_READ_BIT)},
           image, width, height,
           {layout_barrier(image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                           VK_ACCESS_TRANSFER_READ_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT)});
    out.texels.resize(size);
    std::memcpy(out.texels.data(), mapped_, size);
    out.rgba = display_rgba(format, out.texels, static_cast<std::size_t>(width) * height);
    return out;
}

namespace {

VkImageMemoryBarrier depth_barrier(VkImage image, VkImageLayout from, VkImageLayout to, VkAccessFlags src, VkAccessFlags dst) {
    VkImageMemoryBarrier b = layout_barrier(image, from, to, src, dst);
    b.subresourceRange.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    return b;
}

}  // namespace

void FrameInspector::prepare_depth(VkImage image) {
    submit({depth_barrier(image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, 0, 0)},
           VK_NULL_HANDLE, 0, 0, {});
}

std::vector<float> FrameInspector::read_depth(VkImage image, VkFormat format, std::uint32_t width, std::uint32_t height) {
    const bool d16 = format == VK_FORMAT_D16_UNORM;
    const std::size_t n = static_cast<std::size_t>(width) * height;
    ensure_buffer(n * (d16 ? 2 : 4));
    const VkAccessFlags app_writes = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    submit({depth_barrier(image, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, app_writes,
                          VK_ACCESS_TRANSFER_READ_BIT)},
           image, width, height,
           {depth_barrier(image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                          VK_ACCESS_TRANSFER_READ_BIT, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT)},
           VK_IMAGE_ASPECT_DEPTH_BIT);
    std::vector<float> out(n);
    if (d16) {
        const auto* p = static_cast<const std::uint16_t*>(mapped_);
        for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<float>(p[i]) / 65535.0f;
    } else {
        std::memcpy(out.data(), mapped_, n * 4);
    }
    return out;
}

void write_eye_png(const std::string& path, const EyeImage& image) {
    stbi_write_png(path.c_str(), static_cast<int>(image.width), static_cast<int>(image.height), 4, image.rgba.data(),
                   static_cast<int>(image.width * 4));
}

ImageDifference compare_with_png(const EyeImage& image, const std::string& png_path) {
    ImageDifference d;
    int w = 0, h = 0, channels = 0;
    stbi_uc* png = stbi_load(png_path.c_str(), &w, &h, &channels, 4);
    if (!png) return d;
    if (static_cast<std::uint32_t>(w) == image.width && static_cast<std::uint32_t>(h) == image.height &&
        image.rgba.size() == static_cast<std::size_t>(w) * h * 4) {
        std::size_t n = static_cast<std::size_t>(w) * h, differ = 0;
        int worst = 0;
        for (std::size_t i = 0; i < n; ++i) {
            int pixel_worst = 0;
            for (int c = 0; c < 3; ++c) {
                int mine = image.rgba[4 * i + c];
                pixel_worst = std::max(pixel_worst, std::abs(mine - int(png[4 * i + c])));
            }
            worst = std::max(worst, pixel_worst);
            if (pixel_worst > 2) ++differ;
        }
        d.compared = true;
        d.differ_fraction = static_cast<double>(differ) / static_cast<double>(n);
        d.max_diff = worst;
    }
    stbi_image_free(png);
    return d;
}

ColourComparison compare_colour_with_png(const EyeImage& image, const std::string& png_path, double tolerance) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* png = stbi_load(png_path.c_str(), &w, &h, &channels, 4);
    if (!png) return {};
    const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
    const std::size_t png_pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    ColourComparison result = static_cast<std::uint32_t>(w) == image.width && static_cast<std::uint32_t>(h) == image.height
                                  ? compare_colour(image.format, image.texels, png, pixels, tolerance)
                                  : compare_mean_colour(image.format, image.texels, pixels, png, png_pixels, tolerance);
    stbi_image_free(png);
    return result;
}

}  // namespace fgxrt
