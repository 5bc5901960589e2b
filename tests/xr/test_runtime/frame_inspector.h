#pragma once
// Reads back the swapchain images fgplay submits (on fgplay's own VkDevice and queue, as a
// compositor would) and judges them: the right size and format, not blank, and the two eyes
// different.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "swapchain_colour.h"

namespace fgxrt {

struct EyeImage {
    std::uint32_t width = 0, height = 0;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::vector<std::uint8_t> texels;   // as stored, in `format`
    std::vector<std::uint8_t> rgba;     // what the display shows: the texels decoded as the spec says (swapchain_colour.h), sRGB RGBA8
};

struct FrameVerdict {
    std::vector<std::string> problems;
    double mean_luma[2] = {0.0, 0.0};
    double eyes_differ_fraction = 0.0;
};

// Blank: every channel within 4 levels over the whole image. The eyes differ when at least 1 %
// of the pixels differ by more than 2 levels in some channel.
FrameVerdict judge_stereo_pair(const EyeImage& left, const EyeImage& right);

class FrameInspector {
public:
    FrameInspector(VkPhysicalDevice physical, VkDevice device, std::uint32_t queue_family, std::uint32_t queue_index);
    ~FrameInspector();
    FrameInspector(const FrameInspector&) = delete;
    FrameInspector& operator=(const FrameInspector&) = delete;

    // Puts a new swapchain image into COLOR_ATTACHMENT_OPTIMAL, the layout apps receive.
    void prepare(VkImage image);
    // Copies an image in COLOR_ATTACHMENT_OPTIMAL (and leaves it there); waits for the copy.
    EyeImage read(VkImage image, VkFormat format, std::uint32_t width, std::uint32_t height);
    // The same for depth swapchain images (D32_SFLOAT or D16_UNORM, DEPTH_STENCIL_ATTACHMENT_OPTIMAL):
    // the depth values as floats in [0, 1].
    void prepare_depth(VkImage image);
    std::vector<float> read_depth(VkImage image, VkFormat format, std::uint32_t width, std::uint32_t height);

private:
    void submit(const std::vector<VkImageMemoryBarrier>& before, VkImage copy_from, std::uint32_t width,
                std::uint32_t height, const std::vector<VkImageMemoryBarrier>& after,
                VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT);
    void ensure_buffer(VkDeviceSize size);

    VkPhysicalDevice physical_;
    VkDevice device_;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize buffer_size_ = 0;
    void* mapped_ = nullptr;
};

// What the display shows of an eye image against a PNG of the same size (RGB).
struct ImageDifference {
    bool compared = false;            // false: no such PNG, or a different size
    double differ_fraction = 1.0;     // pixels with some channel more than 2 levels apart
    int max_diff = 255;
};
ImageDifference compare_with_png(const EyeImage& image, const std::string& png_path);

// The eye, decoded as the spec says for its format, against the PNG fgplay wrote for the same
// frame (fgplay xr --record): pixel by pixel at the same size, by the mean colour when fgplay
// rendered at another size and scaled. Not compared: no such PNG.
ColourComparison compare_colour_with_png(const EyeImage& image, const std::string& png_path, double tolerance);

// A PNG of what the display shows of an eye image ($FG_XR_TEST_DUMP).
void write_eye_png(const std::string& path, const EyeImage& image);

}  // namespace fgxrt
