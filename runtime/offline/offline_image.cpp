#include "offline_image.h"

#include <Imath/half.h>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <png.h>
#include <stdexcept>

#include "frame/aov_images.h"

namespace fg {

namespace {

constexpr const char* kFormatNames[] = {"png", "png16", "exr"};

std::size_t beauty_index() {
    const auto images = aov_images();
    for (std::size_t k = 0; k < images.size(); ++k)
        if (std::string_view(images[k].name) == "beauty") return k;
    throw std::logic_error("no beauty AOV");
}

// Which channels of AOV image `image` hold light or a share of it, averaged over a pixel's samples as
// the picture is: the beauty, the light terms (specular, shadow), the mirror bounce, the light
// through glass, and the AO in the normal image's alpha. Bit 0 is red.
unsigned averaged_channels(std::size_t image) {
    const std::string_view name = aov_images()[image].name;
    if (name == "beauty" || name == "light" || name == "reflection" || name == "refraction") return 0xF;
    if (name == "normal") return 0x8;
    return 0;
}

float half_at(const std::vector<std::byte>& image, std::size_t index) {
    Imath::half h;
    std::memcpy(&h, image.data() + index * 2, 2);
    return static_cast<float>(h);
}

void png_append(png_structp png, png_bytep data, png_size_t size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + size);
}

}  // namespace

bool parse_output_format(const std::string& text, OutputFormat& out) {
    for (int i = 0; i < 3; ++i)
        if (text == kFormatNames[i]) {
            out = static_cast<OutputFormat>(i);
            return true;
        }
    return false;
}

const char* output_format_name(OutputFormat f) { return kFormatNames[static_cast<int>(f)]; }
const char* output_extension(OutputFormat f) { return f == OutputFormat::Exr ? "exr" : "png"; }

std::vector<std::vector<std::byte>> downsample_aovs(std::vector<std::vector<std::byte>> aovs,
                                                     std::uint32_t width, std::uint32_t height, std::uint32_t factor) {
    if (factor <= 1) return aovs;
    const auto images = aov_images();
    const std::size_t in_width = static_cast<std::size_t>(width) * factor;
    std::vector<std::vector<std::byte>> out(aovs.size());
    for (std::size_t k = 0; k < aovs.size(); ++k) {
        if (aovs[k].empty()) continue;   // a term the scene does not have
        const std::size_t pixel = bytes_per_pixel(images[k].format);
        out[k].resize(pixel * width * height);
        for (std::uint32_t y = 0; y < height; ++y)
            for (std::uint32_t x = 0; x < width; ++x) {
                std::byte* to = out[k].data() + (static_cast<std::size_t>(y) * width + x) * pixel;
                const std::size_t sx = x * factor + factor / 2, sy = y * factor + factor / 2;
                std::memcpy(to, aovs[k].data() + (sy * in_width + sx) * pixel, pixel);
                const unsigned averaged = averaged_channels(k);
                if (averaged == 0) continue;
                float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
                for (std::uint32_t j = 0; j < factor; ++j)
                    for (std::uint32_t i = 0; i < factor; ++i) {
                        const std::size_t at = (static_cast<std::size_t>(y * factor + j) * in_width + x * factor + i) * 4;
                        for (int c = 0; c < 4; ++c) sum[c] += half_at(aovs[k], at + c);
                    }
                for (int c = 0; c < 4; ++c) {
                    if (!(averaged & (1u << c))) continue;
                    Imath::half h(sum[c] / static_cast<float>(factor * factor));
                    std::memcpy(to + c * 2, &h, 2);
                }
            }
    }
    return out;
}

void add_samples(AovSums& sums, const std::vector<std::vector<std::byte>>& aovs, const SampledTiles* sampled,
                 std::uint32_t width) {
    sums.resize(aovs.size());
    for (std::size_t k = 0; k < aovs.size(); ++k) {
        if (averaged_channels(k) == 0 || aovs[k].empty()) continue;   // geometry, or a term the scene lacks
        std::vector<float>& sum = sums[k];
        sum.resize(aovs[k].size() / 2, 0.0f);
        for (std::size_t i = 0; i < sum.size(); ++i) {
            const std::size_t pixel = i / 4;
            if (sampled && !sampled->takes(static_cast<std::uint32_t>(pixel % width / 8), static_cast<std::uint32_t>(pixel / width / 8)))
                continue;
            sum[i] += half_at(aovs[k], i);
        }
    }
}

void mean_samples(std::vector<std::vector<std::byte>>& aovs, const AovSums& sums, const std::vector<std::uint32_t>& counts) {
    for (std::size_t k = 0; k < sums.size() && k < aovs.size(); ++k) {
        const unsigned averaged = averaged_channels(k);
        for (std::size_t i = 0; i < sums[k].size() && 2 * i < aovs[k].size(); ++i) {
            if (!(averaged & (1u << (i % 4)))) continue;
            Imath::half h(sums[k][i] / static_cast<float>(std::max<std::uint32_t>(counts.at(i / 4), 1)));
            std::memcpy(aovs[k].data() + 2 * i, &h, 2);
        }
    }
}

std::vector<std::uint8_t> encode_png16(const std::vector<OfflineEye>& eyes, bool stacked) {
    const std::size_t beauty = beauty_index();
    const std::uint32_t eye_w = eyes.at(0).width, eye_h = eyes.at(0).height;
    const std::uint32_t n = static_cast<std::uint32_t>(eyes.size());
    const std::uint32_t width = stacked ? eye_w : eye_w * n, height = stacked ? eye_h * n : eye_h;
    // PNG stores 16-bit samples big-endian.
    std::vector<std::uint8_t> rows(static_cast<std::size_t>(width) * height * 8);
    for (std::uint32_t e = 0; e < n; ++e)
        for (std::uint32_t y = 0; y < eye_h; ++y)
            for (std::uint32_t x = 0; x < eye_w; ++x) {
                const std::size_t from = (static_cast<std::size_t>(y) * eye_w + x) * 4;
                const std::uint32_t ox = stacked ? x : x + e * eye_w, oy = stacked ? y + e * eye_h : y;
                std::uint8_t* to = &rows[(static_cast<std::size_t>(oy) * width + ox) * 8];
                for (int c = 0; c < 4; ++c) {
                    double v = half_at(eyes[e].aovs[beauty], from + c);
                    auto q = static_cast<std::uint16_t>(std::lround(65535.0 * (c == 3 ? std::clamp(v, 0.0, 1.0) : tonemap_beauty(v))));
                    to[c * 2] = static_cast<std::uint8_t>(q >> 8);
                    to[c * 2 + 1] = static_cast<std::uint8_t>(q & 0xff);
                }
            }
    std::vector<std::uint8_t> out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw std::runtime_error("libpng could not encode a 16-bit PNG");
    }
    png_set_write_fn(png, &out, png_append, nullptr);
    // zlib's default level takes 2.5-6x as long on 16-bit samples for files 10-35 % smaller: level 1
    // keeps the encoding within the next frame's rendering.
    png_set_compression_level(png, 1);
    png_set_IHDR(png, info, width, height, 16, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    // The values are display-encoded, as the 8-bit PNG's are: say sRGB, not linear.
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (std::uint32_t y = 0; y < height; ++y) png_write_row(png, &rows[static_cast<std::size_t>(y) * width * 8]);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
}

}  // namespace fg
