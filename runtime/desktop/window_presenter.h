#pragma once
// A GLFW window with a Vulkan swapchain: the frame graph's final images are blitted into it,
// one eye filling the window or both side by side. Vulkan needs the window system's instance
// extensions and VK_KHR_swapchain on the device, so the presenter supplies the vk::Context hooks.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "image_output.h"
#include "vk/context.h"
#include "vk/image.h"

struct GLFWwindow;

namespace fg::desktop {

class WindowPresenter {
public:
    // Opens the window (throws std::runtime_error with the reason when there is no display).
    WindowPresenter(std::uint32_t width, std::uint32_t height, const std::string& title);
    ~WindowPresenter();
    WindowPresenter(const WindowPresenter&) = delete;
    WindowPresenter& operator=(const WindowPresenter&) = delete;

    // Hooks that add the surface extensions to the instance and VK_KHR_swapchain to the device.
    static vk::ContextCreationHooks context_hooks();
    // Creates the surface and swapchain; call once the Context exists.
    void attach(const vk::Context& ctx);
    // Destroys the swapchain and surface; call before the Context goes away.
    void detach();

    // Blits `left` (and `right`, side by side, when given) and presents. With `capture`, the
    // presented pixels are read back into it (a screenshot of the window's content).
    void present(vk::StorageImage& left, vk::StorageImage* right, Rgba8Image* capture = nullptr);

    GLFWwindow* window() const { return window_; }
    void set_title(const std::string& title);
    bool should_close() const;

private:
    void create_swapchain();
    void destroy_swapchain();

    GLFWwindow* window_ = nullptr;
    const vk::Context* ctx_ = nullptr;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    std::vector<VkImage> images_;
    std::vector<VkImageLayout> layouts_;
    VkFence acquired_ = VK_NULL_HANDLE;
};

}  // namespace fg::desktop
