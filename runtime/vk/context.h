#pragma once
// The root of the Vulkan layer: instance, the chosen physical device, one compute queue and the
// logical device. Everything else borrows a `const Context&` and must not outlive it.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/validation_log.h"

namespace fg::vk {

// Lets another API own instance and device creation (OpenXR's XR_KHR_vulkan_enable2 creates both
// so that the headset's compositor can share the device). Each hook replaces one plain Vulkan call.
struct ContextCreationHooks {
    std::function<VkResult(const VkInstanceCreateInfo&, VkInstance&)> create_instance;
    std::function<VkPhysicalDevice(VkInstance)> physical_device;   // the only device to consider
    std::function<VkResult(VkPhysicalDevice, const VkDeviceCreateInfo&, VkDevice&)> create_device;
};

struct ContextOptions {
    bool validation = false;     // also forced on by the environment variable FG_VK_VALIDATION=1
    std::string device;          // index "1" or case-insensitive name substring; empty = automatic
    bool require_timestamps = true;
    bool shader_float64 = false;  // enabled only when asked for and supported
    bool shader_int64 = false;
    // Adds the validation layer's synchronization checks (missing barriers); slow, for tests.
    bool synchronization_validation = false;
    // Where the pipeline cache is loaded from and saved to when the context ends (see
    // pipeline_cache_file.h; user_pipeline_cache_file() is the user's); empty: in memory only.
    std::filesystem::path pipeline_cache_file;
    ContextCreationHooks hooks;
};

class Context {
public:
    explicit Context(const ContextOptions& options = {});
    ~Context();

    // Pinned in memory: every wrapper and the debug messenger keep a pointer to it.
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    Context(Context&&) = delete;
    Context& operator=(Context&&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physical() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    std::uint32_t queue_family() const { return queue_family_; }
    VkPipelineCache pipeline_cache() const { return pipeline_cache_; }

    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    const VkPhysicalDeviceLimits& limits() const { return properties_.limits; }
    const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_properties_; }
    std::string device_name() const { return properties_.deviceName; }
    bool is_cpu_device() const { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
    // Shader invocations the device runs at once; 0 when it does not say (device_occupancy.h).
    std::uint64_t resident_invocations() const { return resident_invocations_; }
    // The name, and how many invocations the device runs at once where it says.
    std::string device_summary() const;

    bool timestamps_supported() const { return timestamp_valid_bits_ > 0 && timestamp_period_ns() > 0.0f; }
    float timestamp_period_ns() const { return properties_.limits.timestampPeriod; }
    std::uint32_t timestamp_valid_bits() const { return timestamp_valid_bits_; }
    bool host_query_reset_enabled() const { return host_query_reset_; }
    bool shader_float64_enabled() const { return shader_float64_; }
    bool shader_int64_enabled() const { return shader_int64_; }
    bool validation_enabled() const { return messenger_ != VK_NULL_HANDLE; }

    // The one queue is shared by every submitter, so submissions are serialized here.
    void submit(VkCommandBuffer cmd, VkFence fence) const;
    void wait_idle() const;

    std::size_t validation_errors() const { return validation_log_->errors(); }
    std::size_t validation_warnings() const { return validation_log_->warnings(); }
    const std::vector<std::string>& validation_messages() const { return validation_log_->messages(); }
    // Outlives the Context, for messages that arrive while it is being destroyed.
    std::shared_ptr<const ValidationLog> validation_log() const { return validation_log_; }

private:
    void create_instance(bool validation, bool synchronization_validation);
    void select_physical_device(const ContextOptions& options);
    void create_device(const ContextOptions& options);
    void create_pipeline_cache();
    void save_pipeline_cache() noexcept;
    void destroy() noexcept;

    std::shared_ptr<ValidationLog> validation_log_ = std::make_shared<ValidationLog>();
    ContextCreationHooks hooks_;

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkPipelineCache pipeline_cache_ = VK_NULL_HANDLE;
    std::filesystem::path pipeline_cache_file_;
    std::size_t pipeline_cache_loaded_bytes_ = 0;
    std::uint32_t queue_family_ = 0;

    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memory_properties_{};
    std::uint32_t timestamp_valid_bits_ = 0;
    std::uint64_t resident_invocations_ = 0;
    bool host_query_reset_ = false;
    bool shader_float64_ = false;
    bool shader_int64_ = false;

    mutable std::mutex queue_mutex_;
};

}  // namespace fg::vk
