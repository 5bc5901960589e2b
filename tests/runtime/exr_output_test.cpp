// OpenEXR output for compositors, read back with OpenEXR's own reader: the beauty is the picture
// before its tone map (the PNG after the same tone map, within a level), Z is the CPU twin's depth,
// misses are +inf, normals are unit length, the camera matrices put each world position on its
// own pixel; frames are resumable like PNG frames; 16-bit PNGs carry the same picture; an
// 8K-wide ODS frame is written within a bounded memory.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <sys/resource.h>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfStandardAttributes.h>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include <stb/stb_image_write.h>

#include "exr_parts.h"
#include "scratch_dir.h"
#include "frame/aov_images.h"
#include "frame/cpu_reference_tracer.h"
#include "offline/frame_record.h"
#include "offline/path_render.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;
using fg::test::ExrPartPixels;
using fg::test::read_exr;

namespace {

// The bulb from the side, the background visible around it.
const char* kStill = R"({
  "format": "fractograph-camera-path", "version": 1,
  "keyframes": [{"time": 0.0, "position": [0.3, 0.7, 2.4], "target": [0, 0, 0]}]
})";

constexpr const char* kChannels[] = {"R", "G", "B", "A", "Z", "P.X", "P.Y", "P.Z", "N.X", "N.Y",
                                     "N.Z", "AO.Y", "albedo.R", "albedo.G", "albedo.B", "diffuse.Y",
                                     "trap.X", "trap.Y", "trap.Z", "trap.W"};

ExrMatrix from_imath(const Imath::M44f& m) {
    ExrMatrix out{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out[i][j] = m[i][j];
    return out;
}

// The passes of one part side by side, 4 x 2 tiles upscaled `zoom` times, for docs/camera-path.md:
// beauty (tone mapped), Z, world position, normal / AO, albedo, diffuse, trap.
void write_passes_sheet(const ExrPartPixels& p, const std::string& file, int zoom) {
    const int tw = p.width * zoom, th = p.height * zoom;
    std::vector<std::uint8_t> sheet(static_cast<std::size_t>(tw * 4) * th * 2 * 3, 0);
    double z_min = 1e30, z_max = 0.0;
    for (float z : p.channels.at("Z"))
        if (std::isfinite(z)) z_min = std::min<double>(z_min, z), z_max = std::max<double>(z_max, z);
    auto tile = [&](int index, auto colour) {
        for (int y = 0; y < th; ++y)
            for (int x = 0; x < tw; ++x) {
                glm::dvec3 c = glm::clamp(colour(x / zoom, y / zoom), glm::dvec3(0.0), glm::dvec3(1.0));
                std::uint8_t* out = &sheet[(static_cast<std::size_t>(y + (index / 4) * th) * tw * 4 + x + (index % 4) * tw) * 3];
                for (int k = 0; k < 3; ++k) out[k] = static_cast<std::uint8_t>(std::lround(255.0 * c[k]));
            }
    };
    auto v = [&](const char* c, int x, int y) { return static_cast<double>(p.at(c, x, y)); };
    tile(0, [&](int x, int y) { return glm::dvec3(tonemap_beauty(v("R", x, y)), tonemap_beauty(v("G", x, y)), tonemap_beauty(v("B", x, y))); });
    tile(1, [&](int x, int y) {
        return glm::dvec3(std::isinf(v("Z", x, y)) ? 0.0 : 1.0 - 0.8 * (v("Z", x, y) - z_min) / (z_max - z_min));
    });
    tile(2, [&](int x, int y) { return 0.5 + 0.4 * glm::dvec3(v("P.X", x, y), v("P.Y", x, y), v("P.Z", x, y)); });
    tile(3, [&](int x, int y) { return 0.5 + 0.5 * glm::dvec3(v("N.X", x, y), v("N.Y", x, y), v("N.Z", x, y)); });
    tile(4, [&](int x, int y) { return glm::dvec3(v("AO.Y", x, y)); });
    tile(5, [&](int x, int y) { return glm::dvec3(v("albedo.R", x, y), v("albedo.G", x, y), v("albedo.B", x, y)); });
    tile(6, [&](int x, int y) { return glm::dvec3(v("diffuse.Y", x, y)); });
    tile(7, [&](int x, int y) { return glm::dvec3(v("trap.X", x, y), v("trap.Y", x, y), std::sqrt(v("trap.W", x, y))); });
    stbi_write_png(file.c_str(), tw * 4, th * 2, 3, sheet.data(), tw * 4 * 3);
}

class ExrOutput : public RuntimeTest {
protected:
    void SetUp() override {
        RuntimeTest::SetUp();
        Diagnostics diag;
        path_ = CameraPath::parse(nlohmann::json::parse(kStill), 1.0, diag);
        ASSERT_TRUE(path_) << diag.format();
        settings_.projection = Projection::Perspective;
        settings_.width = 96;
        settings_.height = 64;
        settings_.format = OutputFormat::Exr;
    }
    Pack pack_ = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    std::optional<CameraPath> path_;
    PathRenderSettings settings_;
    test::ScratchDir dir_{"fg_exr"};
};

}  // namespace

TEST_F(ExrOutput, the_passes_match_the_picture_and_the_cpu_twin_and_the_matrices_find_each_pixel) {
    PathRenderer renderer(test::shared_context(), pack_, *path_, settings_);
    OfflineFrame frame = renderer.render_frame(0);
    const std::string file = (dir_ / "frame.exr").string();
    {
        auto bytes = renderer.encode(frame);
        std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                    static_cast<std::streamsize>(bytes.size()));
    }
    auto parts = read_exr(file);
    ASSERT_EQ(parts.size(), 2u);
    auto cpu = test::cpu_scene(pack_);
    ReferenceSettings rs;
    rs.step_scale = pack_.manifest.find_spec("step_scale")->value;
    rs.epsilon = pack_.manifest.find_spec("epsilon")->value;
    rs.max_steps = static_cast<int>(pack_.manifest.find_spec("max_steps")->value);
    const StereoViews& views = renderer.views();
    for (int eye = 0; eye < 2; ++eye) {
        const ExrPartPixels& p = parts[static_cast<std::size_t>(eye)];
        const std::string name = eye == 0 ? "left" : "right";
        SCOPED_TRACE(name);
        EXPECT_EQ(p.header.name(), name);
        EXPECT_EQ(p.header.view(), name);
        EXPECT_EQ(p.header.compression(), Imf::ZIP_COMPRESSION);
        ASSERT_EQ(p.width, 96);
        ASSERT_EQ(p.height, 64);
        for (const char* c : kChannels) EXPECT_TRUE(p.header.channels().findChannel(c)) << c;
        EXPECT_EQ(p.header.channels().findChannel("R")->type, Imf::HALF);
        EXPECT_EQ(p.header.channels().findChannel("Z")->type, Imf::FLOAT);
        ASSERT_TRUE(Imf::hasWorldToCamera(p.header) && Imf::hasWorldToNDC(p.header));
        const ExrMatrix to_camera = from_imath(Imf::worldToCamera(p.header));
        const ExrMatrix to_ndc = from_imath(Imf::worldToNDC(p.header));

        const View& view = eye == 0 ? views.left : views.right;
        ReferenceDepth ref = reference_depth(*cpu->evaluator, cpu->settings, view, views.pixel_half_diagonal, rs);
        const double cone = std::tan(views.pixel_half_diagonal);
        int hits = 0, misses = 0, picture_off = 0, depth_off = 0, miss_disagrees = 0;
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < p.width; ++x) {
                // The beauty, tone mapped as the frame does it, is the PNG's picture.
                const std::uint8_t* png = &frame.picture.pixels[(static_cast<std::size_t>(y) * frame.picture.width +
                                                                 static_cast<std::size_t>(x + eye * p.width)) * 4];
                for (int c = 0; c < 3; ++c) {
                    double level = 255.0 * tonemap_beauty(p.at(kChannels[c], x, y));
                    if (std::abs(level - png[c]) > 1.0) ++picture_off;
                }
                const float z = p.at("Z", x, y);
                ASSERT_FALSE(std::isnan(z)) << x << "," << y;
                const double t_ref = ref.depth[static_cast<std::size_t>(y * p.width + x)];
                const glm::dvec3 dir = view.ray((x + 0.5) / p.width, (y + 0.5) / p.height);
                if (std::isinf(z)) {
                    ++misses;
                    EXPECT_GT(z, 0.0f);
                    if (t_ref >= 0.0) ++miss_disagrees;
                    continue;
                }
                ++hits;
                if (t_ref < 0.0) {
                    ++miss_disagrees;
                    continue;
                }
                // Camera depth is along the view axis; both stop within a few cone radii of the surface.
                const double z_ref = t_ref * glm::dot(dir, view.forward);
                if (std::abs(z - z_ref) > 4.0 * cone * t_ref) ++depth_off;
                const glm::dvec3 n(p.at("N.X", x, y), p.at("N.Y", x, y), p.at("N.Z", x, y));
                EXPECT_NEAR(glm::length(n), 1.0, 2e-3) << x << "," << y;
                const glm::dvec3 world(p.at("P.X", x, y), p.at("P.Y", x, y), p.at("P.Z", x, y));
                const glm::dvec3 ndc = exr_transform(world, to_ndc);
                EXPECT_NEAR(ndc.x, (x + 0.5) / p.width, 1e-3) << x << "," << y;
                EXPECT_NEAR(ndc.y, (y + 0.5) / p.height, 1e-3) << x << "," << y;
                EXPECT_NEAR(exr_transform(world, to_camera).z, z, 1e-4 * z) << x << "," << y;
            }
        RecordProperty(name, fmt::format("{} hits, {} misses, {} off the picture, {} off the twin's depth, {} miss "
                                         "disagreements", hits, misses, picture_off, depth_off, miss_disagrees));
        EXPECT_GT(hits, p.width * p.height / 5) << "the bulb should fill part of the view";
        EXPECT_GT(misses, p.width * p.height / 10) << "the background should show";
        EXPECT_EQ(picture_off, 0);
        EXPECT_LE(depth_off, hits / 100);
        EXPECT_LE(miss_disagrees, p.width * p.height / 200);
    }
    // The picture in docs/camera-path.md: FG_EXR_SHEET=docs/images/exr_passes.png.
    if (const char* sheet = std::getenv("FG_EXR_SHEET")) write_passes_sheet(parts[0], sheet, 3);
}

TEST_F(ExrOutput, exr_frames_resume_like_png_frames_and_are_the_same_bytes_every_time) {
    const FrameRange frames{0, 1};
    PathRenderer renderer(test::shared_context(), pack_, *path_, settings_);
    const std::string job = settings_fingerprint(settings_);
    PathRunResult first = run_path(renderer, {(dir_ / "a").string(), frames, job, true, false});
    EXPECT_EQ(first.rendered, 1);
    const std::string image = frame_image_path((dir_ / "a").string(), 0, OutputFormat::Exr);
    EXPECT_TRUE(image.ends_with("frame_000000.exr"));
    EXPECT_TRUE(frame_is_done(image, job));
    PathRunResult again = run_path(renderer, {(dir_ / "a").string(), frames, job, true, false});
    EXPECT_EQ(again.skipped, 1);
    // A PNG job's fingerprint differs: its records never count for EXR frames, nor the reverse.
    PathRenderSettings png = settings_;
    png.format = OutputFormat::Png;
    EXPECT_NE(settings_fingerprint(png), job);
    // Deterministic files: shards on other machines write the same bytes.
    PathRenderer other(test::shared_context(), pack_, *path_, settings_);
    run_path(other, {(dir_ / "b").string(), frames, job, false, false});
    std::uint64_t a = 0, b = 0;
    ASSERT_TRUE(hash_file(image, a));
    ASSERT_TRUE(hash_file(frame_image_path((dir_ / "b").string(), 0, OutputFormat::Exr), b));
    EXPECT_EQ(a, b);
}

TEST_F(ExrOutput, supersampling_box_filters_the_beauty_and_takes_the_central_sample_of_the_data_passes) {
    // An equirect panorama: one part, "centre". Rendered 2x2 per pixel, and once at twice the size
    // with half the detail, so that both hit by the output pixel of the small image.
    settings_.projection = Projection::Equirect;
    settings_.width = 64;
    settings_.height = 32;
    auto write_read = [&](const PathRenderSettings& s, const std::string& name) {
        PathRenderer renderer(test::shared_context(), pack_, *path_, s);
        auto bytes = renderer.encode(renderer.render_frame(0));
        const std::string file = (dir_ / name).string();
        std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                    static_cast<std::streamsize>(bytes.size()));
        return read_exr(file);
    };
    PathRenderSettings super = settings_;
    super.supersample = 2;
    PathRenderSettings big = settings_;
    big.width *= 2;
    big.height *= 2;
    big.detail = 0.5;
    auto s = write_read(super, "super.exr");
    auto b = write_read(big, "big.exr");
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0].header.name(), "centre");
    EXPECT_TRUE(Imf::hasEnvmap(s[0].header));
    EXPECT_FALSE(Imf::hasWorldToNDC(s[0].header));
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            double mean = 0.0;
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) mean += 0.25 * b[0].at("G", 2 * x + i, 2 * y + j);
            // Half precision of the four samples and of their mean.
            EXPECT_NEAR(s[0].at("G", x, y), mean, 2e-3 * (1.0 + mean)) << x << "," << y;
            EXPECT_EQ(s[0].at("Z", x, y), b[0].at("Z", 2 * x + 1, 2 * y + 1)) << x << "," << y;
            EXPECT_EQ(s[0].at("N.Y", x, y), b[0].at("N.Y", 2 * x + 1, 2 * y + 1)) << x << "," << y;
        }
}

TEST_F(ExrOutput, a_16_bit_png_is_the_picture_with_more_levels) {
    settings_.format = OutputFormat::Png16;
    PathRenderer renderer(test::shared_context(), pack_, *path_, settings_);
    OfflineFrame frame = renderer.render_frame(0);
    auto bytes = renderer.encode(frame);
    int w = 0, h = 0, channels = 0;
    ASSERT_TRUE(stbi_is_16_bit_from_memory(bytes.data(), static_cast<int>(bytes.size())));
    stbi_us* pixels = stbi_load_16_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels, 4);
    ASSERT_TRUE(pixels);
    ASSERT_EQ(static_cast<std::uint32_t>(w), frame.picture.width);
    ASSERT_EQ(static_cast<std::uint32_t>(h), frame.picture.height);
    int off = 0, between = 0;
    for (std::size_t i = 0; i < frame.picture.pixels.size(); ++i) {
        double level = pixels[i] / 257.0;
        if (std::abs(level - frame.picture.pixels[i]) > 1.0) ++off;
        if (std::abs(level - std::round(level)) > 0.05) ++between;
    }
    stbi_image_free(pixels);
    EXPECT_EQ(off, 0);
    // Levels between the 8-bit ones: the point of 16 bits (smooth gradients in the background).
    EXPECT_GT(between, w * h / 4);
}

TEST_F(ExrOutput, an_8k_ods_frame_is_written_within_a_bounded_memory) {
    // A cheap scene: the frame's size, not its fractal, is under test.
    Pack room = test::compile_pack(test::read_source_file("tests/runtime/data/panorama_room.json"));
    Diagnostics diag;
    auto still = CameraPath::parse(nlohmann::json::parse(R"({"format": "fractograph-camera-path", "version": 1,
        "keyframes": [{"time": 0.0, "position": [0, 0, 0], "target": [0, 0, -1]}]})"), 1.0, diag);
    ASSERT_TRUE(still) << diag.format();
    settings_.projection = Projection::Ods;
    settings_.width = 8192;
    settings_.height = 4096;
    PathRenderer renderer(test::shared_context(), room, *still, settings_);
    PathRunResult r = run_path(renderer, {dir_.path().string(), {0, 1}, "8k", false, false});
    ASSERT_EQ(r.rendered, 1);
    // Memory: the frame graph's images (lavapipe's device memory is the process's), one host copy of
    // the AOV images (48 bytes a pixel: the room has no light terms) and of the picture (4), the largest download's staging
    // buffer (an eye's positions, 16), the file, and a gigabyte for the process itself (libraries,
    // compiler, driver); a second copy of the AOVs would not fit (measured before the check below
    // reads the file back).
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const std::uint64_t peak = static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;
    const std::uint64_t pixels = 2ull * 8192 * 4096;
    const std::uint64_t file = std::filesystem::file_size(frame_image_path(dir_.path().string(), 0, OutputFormat::Exr));
    std::uint64_t aov_bytes = 0;
    for (const AovImage& a : aov_images())
        if (aov_image_needed(a, renderer.graph().effects)) aov_bytes += bytes_per_pixel(a.format);
    const std::uint64_t bound = renderer.graph().memory_bytes() + pixels * (aov_bytes + 4) + pixels / 2 * 16 + file + (1ull << 30);
    RecordProperty("peak_rss_mib", static_cast<int>(peak >> 20));
    RecordProperty("write_seconds", fmt::format("{:.1f}", r.write_seconds));
    EXPECT_LE(peak, bound) << "peak resident memory " << (peak >> 20) << " MiB, bound " << (bound >> 20) << " MiB";

    auto parts = read_exr(frame_image_path(dir_.path().string(), 0, OutputFormat::Exr), {"Z"});
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_EQ(parts[0].width, 8192);
    EXPECT_EQ(parts[1].height, 4096);
    EXPECT_TRUE(Imf::hasEnvmap(parts[0].header));
    // Straight down from the bottom row: the floor, 1 m below the eye (prim.plane, offset 1).
    EXPECT_NEAR(parts[0].at("Z", 4096, 4095), 1.0, 0.01);
}

TEST_F(ExrOutput, a_lit_scene_writes_its_light_terms_as_passes_and_a_scene_without_them_none) {
    Pack lit = test::compile_pack(test::read_source_file("graphs/examples/lit_mandelbulb.json"));
    auto channels_of = [&](const Pack& pack, const std::string& sub) {
        PathRenderer renderer(test::shared_context(), pack, *path_, settings_);
        run_path(renderer, {(dir_ / sub).string(), {0, 1}, "light terms", false, false});
        return read_exr(frame_image_path((dir_ / sub).string(), 0, OutputFormat::Exr)).at(0);
    };
    ExrPartPixels with = channels_of(lit, "lit"), without = channels_of(pack_, "plain");
    for (const char* c : {"shadow.Y", "specular.R", "specular.G", "specular.B"}) {
        EXPECT_TRUE(with.channels.count(c)) << c;
        EXPECT_FALSE(without.channels.count(c)) << c;
    }
    EXPECT_FALSE(with.channels.count("reflection.R")) << "the lit bulb does not reflect";
    // The bulb shadows itself: some of its points lie mostly in shadow, some in full light.
    std::size_t dark = 0, lit_points = 0;   // below a half, above 0.9
    for (std::size_t i = 0; i < with.channels.at("shadow.Y").size(); ++i) {
        if (!std::isfinite(with.channels.at("Z")[i])) continue;
        const float s = with.channels.at("shadow.Y")[i];
        EXPECT_TRUE(s >= 0.0f && s <= 1.0f) << s;
        dark += s < 0.5f;
        lit_points += s > 0.9f;
    }
    std::printf("shadow: %zu points below a half, %zu above 0.9\n", dark, lit_points);
    EXPECT_GT(dark, 50u);
    EXPECT_GT(lit_points, 50u);
}
