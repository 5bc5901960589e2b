#include "hard_case_support.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>

namespace fg::test {

std::vector<std::string> hard_case_names() { return source_graph_names("graphs/hard"); }

std::string test_name(std::string name) {
    for (auto& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

std::vector<std::string> formula_case_names() {
    std::vector<std::string> names;
    for (const auto& n : source_graph_names("graphs/formulas")) names.push_back("formulas/" + n);
    for (const auto& n : source_graph_names("graphs/gallery"))
        if (read_source_file("graphs/gallery/" + n + ".json").find("\"fractal.formula\"") != std::string::npos)
            names.push_back("gallery/" + n);
    return names;
}

std::string hard_case_text(const std::string& name) {
    return read_source_file((name.find('/') == std::string::npos ? "graphs/hard/" : "graphs/") + name + ".json");
}

namespace {

float half_to_float(std::uint16_t h) {
    std::uint32_t sign = (h >> 15) & 1u, exp = (h >> 10) & 0x1fu, mant = h & 0x3ffu;
    if (exp == 0x1f) return mant ? std::nanf("") : (sign ? -INFINITY : INFINITY);
    float v = exp == 0 ? std::ldexp(static_cast<float>(mant), -24) : std::ldexp(static_cast<float>(mant | 0x400u), static_cast<int>(exp) - 25);
    return sign ? -v : v;
}

std::vector<float> decode(const std::vector<std::byte>& bytes, ImageFormat f) {
    std::vector<float> out;
    if (f == ImageFormat::RGBA16F) {
        out.resize(bytes.size() / 2);
        for (std::size_t i = 0; i < out.size(); ++i) {
            std::uint16_t h;
            std::memcpy(&h, bytes.data() + 2 * i, 2);
            out[i] = half_to_float(h);
        }
    } else {
        out.resize(bytes.size() / 4);
        std::memcpy(out.data(), bytes.data(), out.size() * 4);
    }
    return out;
}

// A conemarch atlas (see fg_level_rect in common.glsl) has corners no level covers, whose
// contents are undefined: keep only the texels of its levels.
std::vector<float> written_levels(const std::vector<float>& rg, std::uint32_t width, std::uint32_t height,
                                  std::uint32_t levels) {
    std::uint32_t full = 1;
    while (full + (full + 1) / 2 < width) ++full;
    std::vector<float> out;
    std::uint32_t y0 = 0;
    for (std::uint32_t level = 0; level < levels; ++level) {
        std::uint32_t x = level == 0 ? 0 : full, y = level == 0 ? 0 : y0;
        std::uint32_t w = (full + (1u << level) - 1) >> level, h = (height + (1u << level) - 1) >> level;
        for (std::uint32_t j = 0; j < h && y + j < height; ++j)
            for (std::uint32_t i = 0; i < w && x + i < width; ++i)
                for (std::uint32_t c = 0; c < 2; ++c) out.push_back(rg[((y + j) * width + x + i) * 2 + c]);
        if (level > 0) y0 += h;
    }
    return out;
}

}  // namespace

HardRender render_hard_case(const Pack& pack, StereoMode mode, std::map<std::string, double> knobs,
                            bool count_evaluations) {
    FrameSettings fs;
    fs.width = fs.height = kHardCaseSize;
    fs.stereo = mode;
    fs.cone_levels = 4;
    fs.knobs = std::move(knobs);
    fs.count_evaluations = count_evaluations;
    StereoSettings ss;
    ss.width = ss.height = kHardCaseSize;
    ss.world_scale = pack.manifest.scene.world_scale;
    HeadlessRenderer r(shared_context(), pack, fs, ss);
    HardRender out;
    out.frame = r.render(r.scene_camera(), 0.0);
    out.views = r.views();
    for (const auto& img : r.executor().graph().images()) {
        if (img.format == ImageFormat::RGBA8) continue;
        auto values = decode(r.executor().download(img.name), img.format);
        if (img.name.rfind("cone.", 0) == 0) values = written_levels(values, img.width, img.height, fs.cone_levels);
        out.float_images.emplace_back(img.name, std::move(values));
    }
    return out;
}

std::size_t count_not_finite(const std::vector<float>& values) {
    return static_cast<std::size_t>(std::count_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }));
}

OverstepReport check_oversteps(const CpuEvaluator& cpu, const SceneSettings& s, const View& view,
                               const std::vector<float>& depth, double pixel_half_diagonal, double epsilon,
                               int stride, int samples, bool camera_relative) {
    OverstepReport rep;
    const double cone = std::tan(pixel_half_diagonal);
    for (std::uint32_t y = static_cast<std::uint32_t>(stride / 2); y < view.height; y += static_cast<std::uint32_t>(stride))
        for (std::uint32_t x = static_cast<std::uint32_t>(stride / 2); x < view.width; x += static_cast<std::uint32_t>(stride)) {
            glm::dvec3 ro = view.origin;
            glm::dvec3 rd = view.ray((x + 0.5) / view.width, (y + 0.5) / view.height);
            glm::dvec3 oc = s.bounds_center - ro;
            double b = glm::dot(oc, rd), h = b * b - (glm::dot(oc, oc) - s.bounds_radius * s.bounds_radius);
            if (h < 0.0) continue;
            h = std::sqrt(h);
            double t0 = std::max(b - h, 0.0), t1 = std::min(b + h, s.max_distance);
            if (t0 > t1) continue;
            ++rep.rays;
            double hit = depth[static_cast<std::size_t>(y) * view.width + x];
            // Float positions near p are spaced |p| * 2^-23 apart; allow two spacings.
            double spacing = camera_relative ? 0x1.0p-22 * std::max(hit, 0.0) + 0x1.0p-46 * glm::length(ro)
                                             : 0x1.0p-22 * (glm::length(ro) + std::max(hit, 0.0));
            double end = hit >= 0.0 ? hit - epsilon * cone * hit - spacing : t1;
            for (int k = 0; k <= samples && end > t0; ++k) {
                double t = t0 + (end - t0) * k / samples;
                double d = cpu.distance(ro + rd * t);
                if (d < 0.0 && (hit >= 0.0 || d < -spacing)) {
                    (hit >= 0.0 ? rep.overstepped : rep.holes)++;
                    if (rep.examples.size() < 5)
                        rep.examples.push_back(fmt::format("pixel ({}, {}): {} at t = {:.9g}, but the CPU twin is inside at "
                                                           "t = {:.9g} (d = {:.3g})",
                                                           x, y, hit >= 0.0 ? "hit" : "miss", hit, t, d));
                    break;
                }
            }
        }
    return rep;
}

}  // namespace fg::test
