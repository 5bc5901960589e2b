#include "runtime_test_support.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <cstring>

#include "frame/aov_images.h"

namespace fg::test {

std::string read_source_file(const std::string& relative) {
    std::ifstream in(std::string(FG_SOURCE_DIR) + "/" + relative, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::vector<std::string> source_graph_names(const std::string& folder) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(std::string(FG_SOURCE_DIR) + "/" + folder))
        if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

Pack compile_pack(const std::string& graph_text, const std::string& folder) {
    Diagnostics diag;
    CompileOptions options;
    if (!folder.empty()) options.folder = std::string(FG_SOURCE_DIR) + "/" + folder;
    auto result = compile_graph(graph_text, NodeLibrary::builtin(), options, diag);
    if (!result) throw std::runtime_error("compile failed:\n" + diag.format());
    auto bytes = pack_bytes(*result);
    auto pack = read_pack(bytes, diag);
    if (!pack) throw std::runtime_error("pack read failed:\n" + diag.format());
    return std::move(*pack);
}

std::size_t aov_index(const std::string& name) {
    for (std::size_t i = 0; i < aov_images().size(); ++i)
        if (aov_images()[i].name == name) return i;
    throw std::logic_error("no AOV image " + name);
}

FrameSettings aov_frame(std::uint32_t size) {
    FrameSettings fs;
    fs.width = fs.height = size;
    fs.stereo = StereoMode::Naive;
    fs.aovs = true;
    return fs;
}

StereoSettings eye_at_camera(std::uint32_t size) {
    StereoSettings stereo{size, size};
    stereo.ipd_m = 0.0;
    return stereo;
}

std::unique_ptr<CpuScene> cpu_scene(const Pack& pack) {
    auto s = std::make_unique<CpuScene>();
    Diagnostics diag;
    auto ir = load_and_lower(pack.graph, NodeLibrary::builtin(), diag);
    if (!ir) throw std::runtime_error(diag.format());
    s->ir = std::move(*ir);
    s->evaluator = CpuEvaluator::create(s->ir, diag);
    if (!s->evaluator) throw std::runtime_error(diag.format());
    s->settings = s->ir.scene;
    return s;
}

float atlas_cone_bound(const std::vector<std::byte>& atlas, std::uint32_t width, std::uint32_t height,
                       std::uint32_t level, std::uint32_t x, std::uint32_t y) {
    std::uint32_t atlas_width = width + (width + 1) / 2;
    std::uint32_t x0 = level == 0 ? 0 : width, y0 = 0;
    for (std::uint32_t k = 1; k < level; ++k) y0 += (height + (1u << k) - 1) >> k;
    std::size_t at = (static_cast<std::size_t>(y0 + (y >> level)) * atlas_width + x0 + (x >> level)) * 8;
    float texel[2];
    std::memcpy(texel, atlas.data() + at, 8);
    return texel[1];
}

vk::Context& shared_context() {
    static vk::Context ctx([] {
        vk::ContextOptions o;
        o.validation = true;
        o.shader_float64 = true;   // the deep-zoom hard case is a double pack
        return o;
    }());
    return ctx;
}

std::string RuntimeTest::validation_text() {
    std::string s;
    for (const auto& m : shared_context().validation_messages()) s += m + "\n";
    return s;
}

FramePass& pass_named(FrameGraph& g, const std::string& label) {
    for (auto& p : g.passes())
        if (p.label == label) return p;
    throw std::logic_error("no pass " + label);
}

const FramePass& pass_named(const FrameGraph& g, const std::string& label) {
    return pass_named(const_cast<FrameGraph&>(g), label);
}

double psnr(const Rgba8Image& a, const Rgba8Image& b) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (i % 4 == 3) continue;
        double d = (static_cast<double>(a.pixels[i]) - b.pixels[i]) / 255.0;
        sum += d * d;
        ++n;
    }
    return sum == 0.0 ? 99.0 : 10.0 * std::log10(static_cast<double>(n) / sum);
}

}  // namespace fg::test
