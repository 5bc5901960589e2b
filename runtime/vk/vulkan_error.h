#pragma once
// Every failing Vulkan call becomes one exception type that keeps the VkResult, so callers can
// tell a lost device from an out-of-memory without parsing text.
#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace fg::vk {

class VulkanError : public std::runtime_error {
public:
    VulkanError(VkResult result, const std::string& message);

    VkResult result() const noexcept { return result_; }

private:
    VkResult result_;
};

// "VK_ERROR_DEVICE_LOST" for VK_ERROR_DEVICE_LOST; "VK_RESULT_UNKNOWN" for codes this build
// does not know (newer drivers may return newer codes).
const char* result_name(VkResult result) noexcept;

// Throws VulkanError("<what> failed: <RESULT_NAME>") when `result` is an error code. Positive
// codes (VK_INCOMPLETE, VK_TIMEOUT, ...) are statuses, not failures, and are left to the caller.
void check(VkResult result, const char* what);

}  // namespace fg::vk
