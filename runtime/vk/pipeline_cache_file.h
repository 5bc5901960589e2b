#pragma once
// The Vulkan pipeline cache kept on disk between runs, one file per user: a second run of the same
// pack gives the driver back what it compiled the first time. The file is only ever a hint: one
// written by another driver or device, or damaged, is ignored (and replaced on exit).
#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace fg::vk {

// $FG_PIPELINE_CACHE (a folder; "off" disables it), else $XDG_CACHE_HOME/fractograph, else
// ~/.cache/fractograph, with the file name pipelines.bin. Empty when disabled or there is no home.
std::filesystem::path user_pipeline_cache_file();

// Whether `data` starts with the header this device writes (Vulkan spec, "Pipeline Cache"):
// header version one, and the device's vendor ID, device ID and pipeline cache UUID.
bool pipeline_cache_fits(std::span<const std::byte> data, const VkPhysicalDeviceProperties& device);

// The file's bytes when they fit this device, else nothing (missing, unreadable, foreign, corrupt).
std::vector<std::byte> read_pipeline_cache(const std::filesystem::path& file, const VkPhysicalDeviceProperties& device);

// Written to a temporary file beside it, then renamed over it: a reader never sees half a file,
// and two processes exiting at once leave one whole cache. False when it could not be written.
bool write_pipeline_cache(const std::filesystem::path& file, std::span<const std::byte> data);

}  // namespace fg::vk
