#include "environment_image.h"

#include <fmt/format.h>

namespace fg {

namespace {
constexpr std::uint64_t kMaxWidth = 8192, kMaxHeight = 4096;

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
std::uint32_t get_u32(std::span<const std::uint8_t> b, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t(b[at + i]) << (8 * i);
    return v;
}
}  // namespace

std::vector<std::uint8_t> environment_payload(const EnvironmentImage& image) {
    std::vector<std::uint8_t> out;
    out.reserve(8 + image.rgba.size() * 2);
    put_u32(out, image.width);
    put_u32(out, image.height);
    for (std::uint16_t h : image.rgba) {
        out.push_back(static_cast<std::uint8_t>(h & 0xff));
        out.push_back(static_cast<std::uint8_t>(h >> 8));
    }
    return out;
}

std::optional<EnvironmentImage> environment_from_payload(std::span<const std::uint8_t> payload, std::string& error) {
    if (payload.size() < 8) {
        error = "the environment chunk is shorter than its 8-byte header";
        return std::nullopt;
    }
    EnvironmentImage image;
    image.width = get_u32(payload, 0);
    image.height = get_u32(payload, 4);
    if (image.width == 0 || image.height == 0 || image.width > kMaxWidth || image.height > kMaxHeight) {
        error = fmt::format("the environment image is {}x{}; it may have 1 to {} columns and 1 to {} rows", image.width,
                            image.height, kMaxWidth, kMaxHeight);
        return std::nullopt;
    }
    const std::uint64_t texels = std::uint64_t(image.width) * image.height;
    if (payload.size() != 8 + texels * 8) {
        error = fmt::format("the environment chunk holds {} bytes; a {}x{} image needs {}", payload.size(), image.width,
                            image.height, 8 + texels * 8);
        return std::nullopt;
    }
    image.rgba.resize(texels * 4);
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        image.rgba[i] = static_cast<std::uint16_t>(payload[8 + 2 * i] | (payload[9 + 2 * i] << 8));
    return image;
}

}  // namespace fg
