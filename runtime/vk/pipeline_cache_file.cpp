#include "vk/pipeline_cache_file.h"

#include <cstring>
#include <fstream>
#include <system_error>

#include "atomic_file.h"
#include "user_cache_folder.h"

namespace fg::vk {

std::filesystem::path user_pipeline_cache_file() {
    const std::filesystem::path folder = user_cache_folder("FG_PIPELINE_CACHE");
    return folder.empty() ? folder : folder / "pipelines.bin";
}

bool pipeline_cache_fits(std::span<const std::byte> data, const VkPhysicalDeviceProperties& device) {
    VkPipelineCacheHeaderVersionOne header{};
    if (data.size() < sizeof(header)) return false;
    std::memcpy(&header, data.data(), sizeof(header));
    return header.headerSize >= sizeof(header) && header.headerSize <= data.size() &&
           header.headerVersion == VK_PIPELINE_CACHE_HEADER_VERSION_ONE && header.vendorID == device.vendorID &&
           header.deviceID == device.deviceID &&
           std::memcmp(header.pipelineCacheUUID, device.pipelineCacheUUID, VK_UUID_SIZE) == 0;
}

std::vector<std::byte> read_pipeline_cache(const std::filesystem::path& file, const VkPhysicalDeviceProperties& device) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return {};
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.empty()) return {};   // memcpy from an empty vector's null data is undefined
    std::vector<std::byte> data(bytes.size());
    std::memcpy(data.data(), bytes.data(), bytes.size());
    return pipeline_cache_fits(data, device) ? data : std::vector<std::byte>{};
}

bool write_pipeline_cache(const std::filesystem::path& file, std::span<const std::byte> data) {
    std::error_code error;
    std::filesystem::create_directories(file.parent_path(), error);
    Diagnostics ignored;   // the cache is a hint: a run that cannot keep it builds its pipelines again
    return write_file_atomically(file.string(), {reinterpret_cast<const std::uint8_t*>(data.data()), data.size()}, ignored);
}

}  // namespace fg::vk
