#pragma once
// The instance's and a physical device's extensions, and whether a list names one.
#include <vector>

#include <vulkan/vulkan.h>

namespace fg::vk {

std::vector<VkExtensionProperties> instance_extensions(const char* layer);
std::vector<VkExtensionProperties> device_extensions(VkPhysicalDevice physical);
bool has_extension(const std::vector<VkExtensionProperties>& extensions, const char* name);

}  // namespace fg::vk
