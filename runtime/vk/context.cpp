#include "vk/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include <fmt/format.h>

#include "vk/device_features.h"
#include "vk/device_occupancy.h"
#include "vk/device_selection.h"
#include "vk/extensions.h"
#include "vk/log.h"
#include "vk/pipeline_cache_file.h"
#include "vk/vulkan_error.h"

namespace fg::vk {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool validation_forced_by_environment() {
    const char* value = std::getenv("FG_VK_VALIDATION");
    return value && std::string_view(value) == "1";
}

std::vector<VkLayerProperties> instance_layers() {
    std::uint32_t count = 0;
    check(vkEnumerateInstanceLayerProperties(&count, nullptr), "vkEnumerateInstanceLayerProperties");
    std::vector<VkLayerProperties> layers(count);
    check(vkEnumerateInstanceLayerProperties(&count, layers.data()), "vkEnumerateInstanceLayerProperties");
    layers.resize(count);
    return layers;
}

std::vector<VkQueueFamilyProperties> queue_families(VkPhysicalDevice physical) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
    families.resize(count);
    return families;
}

VkDebugUtilsMessengerCreateInfoEXT messenger_info(ValidationLog* validation_log) {
    VkDebugUtilsMessengerCreateInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = debug_messenger_callback;
    info.pUserData = validation_log;
    return info;
}

}  // namespace

Context::Context(const ContextOptions& options) {
    try {
        hooks_ = options.hooks;
        create_instance(options.validation || validation_forced_by_environment(),
                        options.synchronization_validation);
        select_physical_device(options);
        create_device(options);
    } catch (...) {
        // The destructor does not run for a half-built object.
        destroy();
        throw;
    }
}

Context::~Context() { destroy(); }

void Context::create_instance(bool validation, bool synchronization_validation) {
    // Looked up rather than called directly: a Vulkan 1.0 loader does not export it.
    auto enumerate_version = reinterpret_cast<PFN_vkEnumerateInstanceVersion>(
        vkGetInstanceProcAddr(VK_NULL_HANDLE, "vkEnumerateInstanceVersion"));
    std::uint32_t loader_version = VK_API_VERSION_1_0;
    if (enumerate_version) check(enumerate_version(&loader_version), "vkEnumerateInstanceVersion");
    if (loader_version < VK_API_VERSION_1_3)
        throw VulkanError(VK_ERROR_INCOMPATIBLE_DRIVER,
                          fmt::format("Vulkan 1.3 is required, but the Vulkan loader only provides {}.{}.{}: "
                                      "update libvulkan1",
                                      VK_API_VERSION_MAJOR(loader_version), VK_API_VERSION_MINOR(loader_version),
                                      VK_API_VERSION_PATCH(loader_version)));

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    const std::vector<VkExtensionProperties> available = instance_extensions(nullptr);

    bool debug_utils = false;
    bool validation_features = false;
    if (validation) {
        const auto all_layers = instance_layers();
        const bool layer_present = std::any_of(all_layers.begin(), all_layers.end(), [](const VkLayerProperties& l) {
            return std::strcmp(l.layerName, kValidationLayer) == 0;
        });
        if (!layer_present) {
            logger().warn("validation requested but {} is not installed (Debian: vulkan-validationlayers); "
                          "continuing without it",
                          kValidationLayer);
        } else {
            layers.push_back(kValidationLayer);
            const auto layer_extensions = instance_extensions(kValidationLayer);
            debug_utils = has_extension(available, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) ||
                          has_extension(layer_extensions, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
            validation_features = has_extension(layer_extensions, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
            if (debug_utils) {
                extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
            } else {
                logger().warn("{} is missing: validation messages will not be counted",
                              VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
            }
            if (synchronization_validation && validation_features)
                extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
            else if (synchronization_validation)
                logger().warn("{} is missing: synchronization validation stays off",
                              VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
        }
    }

    VkInstanceCreateFlags flags = 0;
    // Lets MoltenVK-style portability drivers be enumerated; harmless elsewhere.
    if (has_extension(available, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
        extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
        flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    }

    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "Fractograph";
    app.applicationVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
    app.pEngineName = "Fractograph";
    app.engineVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
    app.apiVersion = VK_API_VERSION_1_3;

    // Chained into the instance info so that messages from vkCreateInstance and
    // vkDestroyInstance, where no messenger object exists yet or any more, are counted too.
    VkDebugUtilsMessengerCreateInfoEXT messenger_create = messenger_info(validation_log_.get());

    const VkValidationFeatureEnableEXT sync_validation = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{};
    features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &sync_validation;

    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.flags = flags;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    const void* chain = nullptr;
    if (debug_utils) {
        messenger_create.pNext = chain;
        chain = &messenger_create;
    }
    if (synchronization_validation && validation_features) {
        features.pNext = chain;
        chain = &features;
    }
    info.pNext = chain;

    const VkResult created = hooks_.create_instance ? hooks_.create_instance(info, instance_)
                                                    : vkCreateInstance(&info, nullptr, &instance_);
    if (created == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw VulkanError(created, "no Vulkan device found: install mesa-vulkan-drivers for lavapipe "
                                   "(vkCreateInstance failed: VK_ERROR_INCOMPATIBLE_DRIVER)");
    check(created, "vkCreateInstance");

    if (debug_utils) {
        auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (!create_messenger)
            throw VulkanError(VK_ERROR_EXTENSION_NOT_PRESENT, "vkCreateDebugUtilsMessengerEXT is not available");
        messenger_create.pNext = nullptr;
        check(create_messenger(instance_, &messenger_create, nullptr, &messenger_),
              "vkCreateDebugUtilsMessengerEXT");
    }
}

void Context::select_physical_device(const ContextOptions& options) {
    std::uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()), "vkEnumeratePhysicalDevices");
    devices.resize(count);
    if (hooks_.physical_device) {
        VkPhysicalDevice required = hooks_.physical_device(instance_);
        std::erase_if(devices, [&](VkPhysicalDevice d) { return d != required; });
        if (devices.empty())
            throw VulkanError(VK_ERROR_INITIALIZATION_FAILED, "the physical device required by the caller is not listed");
    }

    std::vector<DeviceCandidate> candidates;
    for (std::uint32_t i = 0; i < devices.size(); ++i) {
        VkPhysicalDeviceProperties props{};
        vkGetPhysicalDeviceProperties(devices[i], &props);
        const auto families = queue_families(devices[i]);

        DeviceCandidate candidate;
        candidate.index = i;
        candidate.name = props.deviceName;
        candidate.type = props.deviceType;
        candidate.api_version = props.apiVersion;
        candidate.compute_family = choose_compute_family(families);
        candidate.timestamps = candidate.compute_family &&
                               families[*candidate.compute_family].timestampValidBits > 0 &&
                               props.limits.timestampPeriod > 0.0f;
        // The 1.3 feature struct may only be chained for a device that knows it.
        if (props.apiVersion >= VK_API_VERSION_1_3) {
            VkPhysicalDeviceVulkan13Features features13{};
            features13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
            VkPhysicalDeviceFeatures2 features{};
            features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
            features.pNext = &features13;
            vkGetPhysicalDeviceFeatures2(devices[i], &features);
            candidate.synchronization2 = features13.synchronization2 == VK_TRUE;
        }
        candidates.push_back(std::move(candidate));
    }

    const DeviceCandidate& chosen = candidates[choose_device(candidates, options.device, options.require_timestamps)];
    physical_ = devices[chosen.index];
    queue_family_ = *chosen.compute_family;
    timestamp_valid_bits_ = chosen.timestamps ? queue_families(physical_)[queue_family_].timestampValidBits : 0;
    vkGetPhysicalDeviceProperties(physical_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_properties_);
    resident_invocations_ = vk::resident_invocations(physical_);
    logger().debug("using Vulkan device {} ({} invocations at once{})", describe(chosen), resident_invocations_,
                   resident_invocations_ ? "" : ": not reported");
}

std::string Context::device_summary() const {
    if (resident_invocations_ == 0) return device_name();
    return fmt::format("{} ({} invocations at once)", device_name(), resident_invocations_);
}

void Context::create_device(const ContextOptions& options) {
    const EnabledFeatures supported = supported_features(physical_);
    host_query_reset_ = supported.host_query_reset;
    shader_float64_ = options.shader_float64 && supported.shader_float64;
    shader_int64_ = options.shader_int64 && supported.shader_int64;
    if (options.shader_float64 && !shader_float64_)
        logger().warn("{} does not support shaderFloat64; double precision stays off", properties_.deviceName);
    if (options.shader_int64 && !shader_int64_)
        logger().warn("{} does not support shaderInt64; 64-bit integers stay off", properties_.deviceName);

    EnabledFeatures wanted;
    wanted.host_query_reset = host_query_reset_;
    wanted.shader_float64 = shader_float64_;
    wanted.shader_int64 = shader_int64_;
    wanted.maintenance4 = supported.maintenance4;
    const DeviceFeatureChain features(wanted);

    std::vector<const char*> extensions;
    // A portability driver must have its subset extension enabled by whoever uses it.
    if (has_extension(device_extensions(physical_), "VK_KHR_portability_subset"))
        extensions.push_back("VK_KHR_portability_subset");

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{};
    queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queue_info.queueFamilyIndex = queue_family_;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;

    VkDeviceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    info.pNext = features.next();
    info.pEnabledFeatures = features.core();
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue_info;
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    check(hooks_.create_device ? hooks_.create_device(physical_, info, device_)
                               : vkCreateDevice(physical_, &info, nullptr, &device_),
          "vkCreateDevice");
    vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

    pipeline_cache_file_ = options.pipeline_cache_file;
    create_pipeline_cache();
}

// Saves recompiling a pipeline built twice in one run and, with a file, one built in an earlier run.
void Context::create_pipeline_cache() {
    std::vector<std::byte> saved;
    if (!pipeline_cache_file_.empty()) saved = read_pipeline_cache(pipeline_cache_file_, properties_);
    VkPipelineCacheCreateInfo cache_info{};
    cache_info.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO;
    cache_info.initialDataSize = saved.size();
    cache_info.pInitialData = saved.empty() ? nullptr : saved.data();
    // A driver may still refuse data whose header it accepted: start empty then.
    if (vkCreatePipelineCache(device_, &cache_info, nullptr, &pipeline_cache_) != VK_SUCCESS) {
        cache_info.initialDataSize = 0;
        cache_info.pInitialData = nullptr;
        saved.clear();
        check(vkCreatePipelineCache(device_, &cache_info, nullptr, &pipeline_cache_), "vkCreatePipelineCache");
    }
    pipeline_cache_loaded_bytes_ = saved.size();
}

// Written only when its size changed (a driver's cache grows with every new pipeline); a cache
// that cannot be saved costs the next run time, never this one an error.
void Context::save_pipeline_cache() noexcept {
    if (pipeline_cache_file_.empty() || !pipeline_cache_) return;
    try {
        std::size_t size = 0;
        if (vkGetPipelineCacheData(device_, pipeline_cache_, &size, nullptr) != VK_SUCCESS || size == 0) return;
        std::error_code error;
        if (size == pipeline_cache_loaded_bytes_ && std::filesystem::exists(pipeline_cache_file_, error)) return;
        std::vector<std::byte> data(size);
        if (vkGetPipelineCacheData(device_, pipeline_cache_, &size, data.data()) != VK_SUCCESS) return;
        data.resize(size);
        write_pipeline_cache(pipeline_cache_file_, data);
    } catch (const std::exception&) {
        // Out of memory for the copy: the next run starts without it.
    }
}

void Context::destroy() noexcept {
    if (device_) {
        vkDeviceWaitIdle(device_);
        save_pipeline_cache();
        if (pipeline_cache_) vkDestroyPipelineCache(device_, pipeline_cache_, nullptr);
        // Still under the messenger: leaked child objects are reported here.
        vkDestroyDevice(device_, nullptr);
    }
    if (messenger_) {
        auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy_messenger) destroy_messenger(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
    pipeline_cache_ = VK_NULL_HANDLE;
    device_ = VK_NULL_HANDLE;
    queue_ = VK_NULL_HANDLE;
    messenger_ = VK_NULL_HANDLE;
    instance_ = VK_NULL_HANDLE;
}

void Context::submit(VkCommandBuffer cmd, VkFence fence) const {
    VkCommandBufferSubmitInfo cmd_info{};
    cmd_info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO;
    cmd_info.commandBuffer = cmd;

    VkSubmitInfo2 submit_info{};
    submit_info.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2;
    submit_info.commandBufferInfoCount = 1;
    submit_info.pCommandBufferInfos = &cmd_info;

    std::lock_guard lock(queue_mutex_);
    check(vkQueueSubmit2(queue_, 1, &submit_info, fence), "vkQueueSubmit2");
}

void Context::wait_idle() const {
    std::lock_guard lock(queue_mutex_);
    check(vkDeviceWaitIdle(device_), "vkDeviceWaitIdle");
}

}  // namespace fg::vk
