#pragma once
// What the validation layer said during a Context's life. It is shared (not owned outright by
// the Context) so a test can still read it after the Context is destroyed: leaked objects are
// only reported while vkDestroyDevice runs.
#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace fg::vk {

class ValidationLog {
public:
    // Called from the debug-utils callback, possibly on several threads at once.
    void record(VkDebugUtilsMessageSeverityFlagBitsEXT severity, std::string message);

    std::size_t errors() const;
    std::size_t warnings() const;
    // Stable reference for reading; read it when no other thread is making Vulkan calls.
    const std::vector<std::string>& messages() const { return messages_; }

private:
    mutable std::mutex mutex_;
    std::size_t errors_ = 0;
    std::size_t warnings_ = 0;
    std::vector<std::string> messages_;
};

// The VK_EXT_debug_utils callback. User data must point at a ValidationLog.
VKAPI_ATTR VkBool32 VKAPI_CALL debug_messenger_callback(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user_data);

}  // namespace fg::vk
