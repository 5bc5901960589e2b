#include "exr_frame.h"

#include <cstring>
#include <fmt/format.h>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfThreading.h>

#include "frame/aov_images.h"

namespace fg {

namespace {

// OpenEXR writes through a stream it can seek back in (the chunk offset table comes last).
class MemoryStream : public Imf::OStream {
public:
    explicit MemoryStream(std::vector<std::uint8_t>& out) : Imf::OStream("memory"), out_(out) {}
    void write(const char c[], int n) override {
        if (at_ + n > out_.size()) out_.resize(at_ + n);
        std::memcpy(out_.data() + at_, c, static_cast<std::size_t>(n));
        at_ += static_cast<std::size_t>(n);
    }
    std::uint64_t tellp() override { return at_; }
    void seekp(std::uint64_t pos) override { at_ = pos; }

private:
    std::vector<std::uint8_t>& out_;
    std::size_t at_ = 0;
};

// One EXR channel: a component of one of the AOV images.
struct Channel {
    const char* name;
    const char* image;      // aov_images() name
    int component;
    Imf::PixelType type;
};

constexpr Channel kChannels[] = {
    {"R", "beauty", 0, Imf::HALF},       {"G", "beauty", 1, Imf::HALF},       {"B", "beauty", 2, Imf::HALF},
    {"A", "beauty", 3, Imf::HALF},       {"Z", "position", 3, Imf::FLOAT},    {"P.X", "position", 0, Imf::FLOAT},
    {"P.Y", "position", 1, Imf::FLOAT},  {"P.Z", "position", 2, Imf::FLOAT},  {"N.X", "normal", 0, Imf::HALF},
    {"N.Y", "normal", 1, Imf::HALF},     {"N.Z", "normal", 2, Imf::HALF},     {"AO.Y", "normal", 3, Imf::HALF},
    {"albedo.R", "albedo", 0, Imf::HALF}, {"albedo.G", "albedo", 1, Imf::HALF}, {"albedo.B", "albedo", 2, Imf::HALF},
    {"diffuse.Y", "albedo", 3, Imf::HALF}, {"trap.X", "trap", 0, Imf::HALF},   {"trap.Y", "trap", 1, Imf::HALF},
    {"trap.Z", "trap", 2, Imf::HALF},    {"trap.W", "trap", 3, Imf::HALF},
    {"specular.R", "light", 0, Imf::HALF}, {"specular.G", "light", 1, Imf::HALF}, {"specular.B", "light", 2, Imf::HALF},
    {"shadow.Y", "light", 3, Imf::HALF},
    {"reflection.R", "reflection", 0, Imf::HALF}, {"reflection.G", "reflection", 1, Imf::HALF},
    {"reflection.B", "reflection", 2, Imf::HALF}, {"refraction.R", "refraction", 0, Imf::HALF},
    {"refraction.G", "refraction", 1, Imf::HALF}, {"refraction.B", "refraction", 2, Imf::HALF},
};

Imath::M44f to_imath(const ExrMatrix& rows) {
    Imath::M44f m;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m[i][j] = static_cast<float>(rows[i][j]);
    return m;
}

Imf::Compression imf_compression(ExrCompression c) {
    switch (c) {
        case ExrCompression::Zip: return Imf::ZIP_COMPRESSION;
        case ExrCompression::Piz: return Imf::PIZ_COMPRESSION;
        case ExrCompression::None: return Imf::NO_COMPRESSION;
    }
    return Imf::ZIP_COMPRESSION;
}

// The AOV image a channel reads, by its index in aov_images().
std::size_t image_of(const Channel& c) {
    const auto images = aov_images();
    std::size_t k = 0;
    while (std::strcmp(images[k].name, c.image) != 0) ++k;
    return k;
}

// A part carries a channel where it has its image: a scene without a term has no image for it
// (aov_image_needed), and its EXR no channel.
bool has_channel(const ExrPart& part, const Channel& c) { return !part.aovs[image_of(c)].empty(); }

Imf::Header part_header(const ExrPart& part, ExrCompression compression) {
    Imf::Header h(static_cast<int>(part.width), static_cast<int>(part.height));
    h.compression() = imf_compression(compression);
    h.setName(part.view);
    h.setType(Imf::SCANLINEIMAGE);
    h.setView(part.view);
    for (const Channel& c : kChannels)
        if (has_channel(part, c)) h.channels().insert(c.name, Imf::Channel(c.type));
    Imf::addWorldToCamera(h, to_imath(part.camera.world_to_camera));
    if (part.camera.world_to_ndc) Imf::addWorldToNDC(h, to_imath(*part.camera.world_to_ndc));
    if (part.panorama) Imf::addEnvmap(h, Imf::ENVMAP_LATLONG);
    return h;
}

}  // namespace

bool parse_exr_compression(const std::string& text, ExrCompression& out) {
    for (ExrCompression c : {ExrCompression::Zip, ExrCompression::Piz, ExrCompression::None})
        if (text == exr_compression_name(c)) {
            out = c;
            return true;
        }
    return false;
}

const char* exr_compression_name(ExrCompression c) {
    switch (c) {
        case ExrCompression::Zip: return "zip";
        case ExrCompression::Piz: return "piz";
        case ExrCompression::None: return "none";
    }
    return "?";
}

ExrCamera exr_camera(const View& view, double world_scale, bool perspective) {
    ExrCamera c;
    ExrMatrix& m = c.world_to_camera;
    const glm::dvec3 axes[3] = {view.right, view.up, view.forward};
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) m[i][j] = axes[j][i] / world_scale;
        m[3][j] = -glm::dot(view.origin, axes[j]) / world_scale;
        m[j][3] = 0.0;
    }
    m[3][3] = 1.0;
    if (!perspective) return c;
    // Camera to NDC: x' = (x/z - left)/(right - left), y' = (up - y/z)/(up - down), w = z.
    const Fov& f = view.fov;
    ExrMatrix ndc{};
    ndc[0][0] = 1.0 / (f.right - f.left);
    ndc[1][1] = -1.0 / (f.up - f.down);
    ndc[2][0] = -f.left / (f.right - f.left);
    ndc[2][1] = f.up / (f.up - f.down);
    ndc[2][3] = 1.0;
    ndc[3][2] = 1.0;   // z' = 1/z after the divide: keeps the matrix invertible
    ExrMatrix product{};   // world_to_camera, then ndc
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) product[i][j] += m[i][k] * ndc[k][j];
    c.world_to_ndc = product;
    return c;
}

glm::dvec3 exr_transform(const glm::dvec3& p, const ExrMatrix& rows) {
    const double in[4] = {p.x, p.y, p.z, 1.0};
    double out[4] = {0.0, 0.0, 0.0, 0.0};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) out[j] += in[i] * rows[i][j];
    return glm::dvec3(out[0], out[1], out[2]) / out[3];
}

std::vector<std::uint8_t> encode_exr(std::span<const ExrPart> parts, ExrCompression compression) {
    // OpenEXR compresses a part's chunks on its own thread pool: every core of a farm node.
    static std::once_flag threads;
    std::call_once(threads, [] { Imf::setGlobalThreadCount(static_cast<int>(std::thread::hardware_concurrency())); });
    std::vector<std::uint8_t> bytes;
    try {
        std::vector<Imf::Header> headers;
        const auto images = aov_images();
        for (const ExrPart& p : parts) {
            if (p.aovs.size() != images.size()) throw std::logic_error("an EXR part needs a place for every AOV image");
            headers.push_back(part_header(p, compression));
        }
        MemoryStream stream(bytes);
        Imf::MultiPartOutputFile file(stream, headers.data(), static_cast<int>(headers.size()));
        for (std::size_t i = 0; i < parts.size(); ++i) {
            const ExrPart& p = parts[i];
            Imf::FrameBuffer fb;
            for (const Channel& c : kChannels) {
                if (!has_channel(p, c)) continue;
                const std::size_t k = image_of(c);
                const std::size_t pixel = bytes_per_pixel(images[k].format);
                const std::size_t component = pixel / 4;
                if (p.aovs[k].size() < pixel * p.width * p.height) throw std::logic_error("an AOV image is too small");
                char* base = const_cast<char*>(reinterpret_cast<const char*>(p.aovs[k].data())) + component * c.component;
                fb.insert(c.name, Imf::Slice(c.type, base, pixel, pixel * p.width));
            }
            Imf::OutputPart out(file, static_cast<int>(i));
            out.setFrameBuffer(fb);
            out.writePixels(static_cast<int>(p.height));
        }
    } catch (const std::exception& e) {
        throw std::runtime_error(fmt::format("OpenEXR: {}", e.what()));
    }
    return bytes;
}

}  // namespace fg
