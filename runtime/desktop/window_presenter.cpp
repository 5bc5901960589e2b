#include "desktop/window_presenter.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/vulkan_error.h"

namespace fg::desktop {

namespace {

void blit(VkCommandBuffer cmd, vk::StorageImage& src, VkImage dst, VkOffset3D lo, VkOffset3D hi) {
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {static_cast<std::int32_t>(src.extent().width), static_cast<std::int32_t>(src.extent().height), 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstOffsets[0] = lo;
    region.dstOffsets[1] = hi;
    vkCmdBlitImage(cmd, src.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                   &region, VK_FILTER_LINEAR);
}

}  // namespace

WindowPresenter::WindowPresenter(std::uint32_t width, std::uint32_t height, const std::string& title) {
    if (!glfwInit()) {
        const char* why = nullptr;
        glfwGetError(&why);
        throw std::runtime_error(fmt::format("cannot open a window ({}); is there a display? Use xvfb-run without one, "
                                             "or `fgplay render` for images",
                                             why ? why : "glfwInit failed"));
    }
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw std::runtime_error("GLFW finds no Vulkan loader with window-system support");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    window_ = glfwCreateWindow(static_cast<int>(width), static_cast<int>(height), title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw std::runtime_error("glfwCreateWindow failed");
    }
}

void WindowPresenter::detach() {
    if (!ctx_) return;
    ctx_->wait_idle();
    destroy_swapchain();
    if (acquired_) vkDestroyFence(ctx_->device(), acquired_, nullptr);
    if (surface_) vkDestroySurfaceKHR(ctx_->instance(), surface_, nullptr);
    acquired_ = VK_NULL_HANDLE;
    surface_ = VK_NULL_HANDLE;
    ctx_ = nullptr;
}

WindowPresenter::~WindowPresenter() {
    detach();
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

vk::ContextCreationHooks WindowPresenter::context_hooks() {
    vk::ContextCreationHooks hooks;
    hooks.create_instance = [](const VkInstanceCreateInfo& info, VkInstance& out) {
        std::uint32_t count = 0;
        const char** required = glfwGetRequiredInstanceExtensions(&count);
        std::vector<const char*> extensions(info.ppEnabledExtensionNames, info.ppEnabledExtensionNames + info.enabledExtensionCount);
        for (std::uint32_t i = 0; i < count; ++i)
            if (std::none_of(extensions.begin(), extensions.end(), [&](const char* e) { return std::strcmp(e, required[i]) == 0; }))
                extensions.push_back(required[i]);
        VkInstanceCreateInfo copy = info;
        copy.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
        copy.ppEnabledExtensionNames = extensions.data();
        return vkCreateInstance(&copy, nullptr, &out);
    };
    hooks.create_device = [](VkPhysicalDevice physical, const VkDeviceCreateInfo& info, VkDevice& out) {
        std::vector<const char*> extensions(info.ppEnabledExtensionNames, info.ppEnabledExtensionNames + info.enabledExtensionCount);
        extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
        VkDeviceCreateInfo copy = info;
        copy.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
        copy.ppEnabledExtensionNames = extensions.data();
        return vkCreateDevice(physical, &copy, nullptr, &out);
    };
    return hooks;
}

void WindowPresenter::attach(const vk::Context& ctx) {
    ctx_ = &ctx;
    vk::check(glfwCreateWindowSurface(ctx.instance(), window_, nullptr, &surface_), "glfwCreateWindowSurface");
    VkBool32 supported = VK_FALSE;
    vk::check(vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physical(), ctx.queue_family(), surface_, &supported),
              "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!supported) throw std::runtime_error(fmt::format("{} cannot present to this window from its compute queue", ctx.device_name()));
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    vk::check(vkCreateFence(ctx.device(), &fi, nullptr, &acquired_), "vkCreateFence");
    create_swapchain();
}

void WindowPresenter::create_swapchain() {
    VkSurfaceCapabilitiesKHR caps;
    vk::check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_->physical(), surface_, &caps), "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_->physical(), surface_, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_->physical(), surface_, &count, formats.data());
    // UNORM: the final image already holds display values.
    VkSurfaceFormatKHR chosen = formats.at(0);
    for (const auto& f : formats)
        if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) chosen = f;
    format_ = chosen.format;
    extent_ = caps.currentExtent;
    if (extent_.width == UINT32_MAX) {
        int w = 0, h = 0;
        glfwGetFramebufferSize(window_, &w, &h);
        extent_ = {static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h)};
    }
    VkSwapchainCreateInfoKHR si{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    si.surface = surface_;
    si.minImageCount = std::max(2u, caps.minImageCount);
    if (caps.maxImageCount) si.minImageCount = std::min(si.minImageCount, caps.maxImageCount);
    si.imageFormat = chosen.format;
    si.imageColorSpace = chosen.colorSpace;
    si.imageExtent = extent_;
    si.imageArrayLayers = 1;
    si.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    si.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    si.preTransform = caps.currentTransform;
    si.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    si.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    si.clipped = VK_TRUE;
    vk::check(vkCreateSwapchainKHR(ctx_->device(), &si, nullptr, &swapchain_), "vkCreateSwapchainKHR");
    vkGetSwapchainImagesKHR(ctx_->device(), swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(ctx_->device(), swapchain_, &count, images_.data());
    layouts_.assign(count, VK_IMAGE_LAYOUT_UNDEFINED);
}

void WindowPresenter::destroy_swapchain() {
    if (swapchain_) vkDestroySwapchainKHR(ctx_->device(), swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
}

void WindowPresenter::present(vk::StorageImage& left, vk::StorageImage* right, Rgba8Image* capture) {
    std::uint32_t index = 0;
    vk::check(vkAcquireNextImageKHR(ctx_->device(), swapchain_, UINT64_MAX, VK_NULL_HANDLE, acquired_, &index),
              "vkAcquireNextImageKHR");
    vk::check(vkWaitForFences(ctx_->device(), 1, &acquired_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    vk::check(vkResetFences(ctx_->device(), 1, &acquired_), "vkResetFences");
    VkImage target = images_[index];
    const bool can_capture = capture != nullptr;
    std::unique_ptr<vk::Buffer> readback;
    if (can_capture)
        readback = std::make_unique<vk::Buffer>(*ctx_, static_cast<VkDeviceSize>(extent_.width) * extent_.height * 4,
                                                VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryKind::HostVisible);
    vk::OneShot::run(*ctx_, [&](VkCommandBuffer cmd) {
        for (vk::StorageImage* src : {&left, right})
            if (src) src->transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, vk::access::compute_write, vk::access::transfer_read);
        vk::image_layout_barrier(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, vk::access::none,
                                 vk::access::transfer_write);
        VkClearColorValue black{};
        VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &range);
        vk::memory_barrier(cmd, vk::access::transfer_write, vk::access::transfer_write);
        // Each eye keeps its aspect ratio, centred in the window (one eye) or in its half (two).
        const auto w = static_cast<std::int32_t>(extent_.width), h = static_cast<std::int32_t>(extent_.height);
        auto fit = [&](vk::StorageImage& src, std::int32_t x0, std::int32_t area_w) {
            double aspect = static_cast<double>(src.extent().width) / src.extent().height;
            std::int32_t ew = std::min(area_w, static_cast<std::int32_t>(h * aspect));
            std::int32_t eh = std::min(h, static_cast<std::int32_t>(ew / aspect));
            std::int32_t x = x0 + (area_w - ew) / 2, y = (h - eh) / 2;
            blit(cmd, src, target, {x, y, 0}, {x + ew, y + eh, 1});
        };
        if (!right) {
            fit(left, 0, w);
        } else {
            fit(left, 0, w / 2);
            fit(*right, w / 2, w / 2);
        }
        VkImageLayout final_layout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
        if (readback) {
            vk::image_layout_barrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                     vk::access::transfer_write, vk::access::transfer_read);
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {extent_.width, extent_.height, 1};
            vkCmdCopyImageToBuffer(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback->handle(), 1, &region);
            vk::transfer_to_host_barrier(cmd);
            vk::image_layout_barrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, final_layout, vk::access::transfer_read,
                                     vk::access::none);
        } else {
            vk::image_layout_barrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, final_layout, vk::access::transfer_write,
                                     vk::access::none);
        }
        for (vk::StorageImage* src : {&left, right})
            if (src) src->transition(cmd, VK_IMAGE_LAYOUT_GENERAL, vk::access::transfer_read, vk::access::compute_read_write);
    });
    if (readback) {
        readback->invalidate();
        capture->width = extent_.width;
        capture->height = extent_.height;
        capture->pixels.resize(static_cast<std::size_t>(extent_.width) * extent_.height * 4);
        std::memcpy(capture->pixels.data(), readback->data(), capture->pixels.size());
        if (format_ == VK_FORMAT_B8G8R8A8_UNORM || format_ == VK_FORMAT_B8G8R8A8_SRGB)
            for (std::size_t i = 0; i + 3 < capture->pixels.size(); i += 4) std::swap(capture->pixels[i], capture->pixels[i + 2]);
        for (std::size_t i = 3; i < capture->pixels.size(); i += 4) capture->pixels[i] = 255;
    }
    VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    pi.swapchainCount = 1;
    pi.pSwapchains = &swapchain_;
    pi.pImageIndices = &index;
    VkResult r = vkQueuePresentKHR(ctx_->queue(), &pi);
    if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR) vk::check(r, "vkQueuePresentKHR");
}

void WindowPresenter::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

bool WindowPresenter::should_close() const { return glfwWindowShouldClose(window_); }

}  // namespace fg::desktop
