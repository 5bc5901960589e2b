#include "vk/validation_log.h"

#include "vk/log.h"

namespace fg::vk {

void ValidationLog::record(VkDebugUtilsMessageSeverityFlagBitsEXT severity, std::string message) {
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
        logger().error("{}", message);
    } else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        logger().warn("{}", message);
    } else {
        logger().info("{}", message);
    }

    std::lock_guard lock(mutex_);
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ++errors_;
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) ++warnings_;
    messages_.push_back(std::move(message));
}

std::size_t ValidationLog::errors() const {
    std::lock_guard lock(mutex_);
    return errors_;
}

std::size_t ValidationLog::warnings() const {
    std::lock_guard lock(mutex_);
    return warnings_;
}

VKAPI_ATTR VkBool32 VKAPI_CALL debug_messenger_callback(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT /*types*/,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user_data) {
    auto* validation_log = static_cast<ValidationLog*>(user_data);
    if (validation_log && data && data->pMessage) {
        // An exception must not unwind through the driver's C frames.
        try {
            validation_log->record(severity, data->pMessage);
        } catch (...) {
        }
    }
    // VK_FALSE: the call that triggered the message must go on as it would without the layer.
    return VK_FALSE;
}

}  // namespace fg::vk
