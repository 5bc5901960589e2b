#include "vk/vulkan_error.h"

#include <string_view>

#include <fmt/format.h>

namespace fg::vk {

VulkanError::VulkanError(VkResult result, const std::string& message)
    : std::runtime_error(message), result_(result) {}

const char* result_name(VkResult result) noexcept {
    switch (result) {
#define FG_VK_RESULT_CASE(name) \
    case name: return #name
        FG_VK_RESULT_CASE(VK_SUCCESS);
        FG_VK_RESULT_CASE(VK_NOT_READY);
        FG_VK_RESULT_CASE(VK_TIMEOUT);
        FG_VK_RESULT_CASE(VK_EVENT_SET);
        FG_VK_RESULT_CASE(VK_EVENT_RESET);
        FG_VK_RESULT_CASE(VK_INCOMPLETE);
        FG_VK_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY);
        FG_VK_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY);
        FG_VK_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED);
        FG_VK_RESULT_CASE(VK_ERROR_DEVICE_LOST);
        FG_VK_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED);
        FG_VK_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT);
        FG_VK_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT);
        FG_VK_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT);
        FG_VK_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER);
        FG_VK_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS);
        FG_VK_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED);
        FG_VK_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL);
        FG_VK_RESULT_CASE(VK_ERROR_UNKNOWN);
        FG_VK_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY);
        FG_VK_RESULT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE);
        FG_VK_RESULT_CASE(VK_ERROR_FRAGMENTATION);
        FG_VK_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS);
        FG_VK_RESULT_CASE(VK_PIPELINE_COMPILE_REQUIRED);
        FG_VK_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR);
        FG_VK_RESULT_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR);
        FG_VK_RESULT_CASE(VK_SUBOPTIMAL_KHR);
        FG_VK_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR);
        FG_VK_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DISPLAY_KHR);
        FG_VK_RESULT_CASE(VK_ERROR_VALIDATION_FAILED_EXT);
        FG_VK_RESULT_CASE(VK_ERROR_INVALID_SHADER_NV);
        FG_VK_RESULT_CASE(VK_ERROR_INVALID_DRM_FORMAT_MODIFIER_PLANE_LAYOUT_EXT);
        FG_VK_RESULT_CASE(VK_ERROR_NOT_PERMITTED_KHR);
        FG_VK_RESULT_CASE(VK_THREAD_IDLE_KHR);
        FG_VK_RESULT_CASE(VK_THREAD_DONE_KHR);
        FG_VK_RESULT_CASE(VK_OPERATION_DEFERRED_KHR);
        FG_VK_RESULT_CASE(VK_OPERATION_NOT_DEFERRED_KHR);
        FG_VK_RESULT_CASE(VK_ERROR_COMPRESSION_EXHAUSTED_EXT);
#undef FG_VK_RESULT_CASE
        default: return "VK_RESULT_UNKNOWN";
    }
}

void check(VkResult result, const char* what) {
    if (result >= 0) return;
    const char* name = result_name(result);
    if (std::string_view(name) == "VK_RESULT_UNKNOWN")
        throw VulkanError(result, fmt::format("{} failed: VkResult {}", what, static_cast<int>(result)));
    throw VulkanError(result, fmt::format("{} failed: {}", what, name));
}

}  // namespace fg::vk
