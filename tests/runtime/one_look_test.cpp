// One look at every resolution: the hit threshold and the normal taps follow the output pixel, so
// sampling changes a picture's noise, never which fractal it shows. For the gallery bulb, box and
// Kleinian, in their own view and the benchmark's filled view: a 1 spp frame and its 4x4
// supersampled frame agree in linear mean within 3 % (marched at their own resolution they were
// 32 % apart), and every ring of a foveated frame (fovea 0.4) agrees with the unfoveated frame.
// Jittered samples accumulated in one frame's memory (`--samples 16`) give the picture of 4x4
// supersampling. Sizes per eye: 96 for supersampling (it marches 384), 256 for the rings (at 96 the
// bulb's outer ring is its silhouette in 2x2 blocks: +31 %, +1.6 % at 256, +0.3 % at 512);
// FG_ONE_LOOK_SIZE sets both (docs/accuracy.md quotes 512).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

#include "bench_views.h"
#include "offline/jittered_samples.h"
#include "offline/linear_light.h"
#include "offline/supersample.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

std::uint32_t size(std::uint32_t otherwise) {
    const char* s = std::getenv("FG_ONE_LOOK_SIZE");
    return s ? static_cast<std::uint32_t>(std::atoi(s)) : otherwise;
}

// Rings around the image centre, in half image heights: the fovea (foveation 0.4), the blend band
// (0.15 wide), the ring just beyond it and the periphery.
constexpr std::array<double, 5> kRingEdges{0.0, 0.4, 0.55, 0.8, 10.0};

// Linear-light mean of the RGB channels in each ring, the whole image last.
std::array<double, 5> ring_means(const Rgba8Image& image) {
    std::array<double, 5> sum{}, count{};
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
            const auto& linear = srgb8_linear_table();
            double v = (linear[p[0]] + linear[p[1]] + linear[p[2]]) / 3.0;
            double r = std::hypot(x + 0.5 - 0.5 * image.width, y + 0.5 - 0.5 * image.height) / (0.5 * image.height);
            for (std::size_t k = 0; k + 1 < kRingEdges.size(); ++k)
                if (r >= kRingEdges[k] && r < kRingEdges[k + 1]) sum[k] += v, count[k] += 1.0;
            sum[4] += v;
            count[4] += 1.0;
        }
    for (std::size_t k = 0; k < sum.size(); ++k) sum[k] /= std::max(count[k], 1.0);
    return sum;
}

struct Look {
    std::string scene, view;
};

class OneLook : public RuntimeTest, public ::testing::WithParamInterface<Look> {};

// The left eye of a per-eye frame at `n` x `n` marched pixels, output pixels `detail` of them wide.
Rgba8Image left_eye(const Pack& pack, const HeadPose& head, double world_scale, std::uint32_t n, double detail,
                    double foveation) {
    FrameSettings fs;
    fs.width = fs.height = n;
    fs.detail_scale = detail;
    fs.foveation = foveation;
    StereoSettings stereo{n, n};
    stereo.world_scale = world_scale;
    HeadlessRenderer renderer(test::shared_context(), pack, fs, stereo);
    return renderer.render(head, 0.0).left;
}

}  // namespace

TEST_P(OneLook, supersampled_and_foveated_frames_show_the_fractal_of_the_1spp_frame) {
    const Look look = GetParam();
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/" + look.scene + ".json"));
    auto cpu = test::cpu_scene(pack);
    bench::BenchView view{"own", {}, cpu->settings.world_scale};
    for (const bench::BenchView& v : bench::make_bench_views(*cpu->evaluator, cpu->settings))
        if (v.name == (look.view == "own" ? "afar" : look.view)) view = v;
    const std::uint32_t n = size(96), rings_n = size(256);

    auto one = ring_means(left_eye(pack, view.head, view.world_scale, n, 1.0, 0.0));
    auto four = ring_means(downsample(left_eye(pack, view.head, view.world_scale, 4 * n, 4.0, 0.0), 4));
    auto full = n == rings_n ? one : ring_means(left_eye(pack, view.head, view.world_scale, rings_n, 1.0, 0.0));
    auto foveated = ring_means(left_eye(pack, view.head, view.world_scale, rings_n, 1.0, 0.4));

    std::string figures = fmt::format("{} {}: linear mean at {}^2 1 spp {:.4f}, 4x4 {:.4f} ({:+.1f} %); foveation 0.4 "
                                      "at {}^2, rings",
                                      look.scene, look.view, n, one[4], four[4], 100.0 * (one[4] / four[4] - 1.0), rings_n);
    for (std::size_t k = 0; k < 4; ++k)
        figures += fmt::format(" {:.2f}-{:.2f}: {:+.1f} %", kRingEdges[k], std::min(kRingEdges[k + 1], 9.99),
                               100.0 * (foveated[k] / full[k] - 1.0));
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_NEAR(one[4] / four[4], 1.0, 0.03) << figures;
    for (std::size_t k = 0; k < 4; ++k)
        if (full[k] > 0.0) EXPECT_NEAR(foveated[k] / full[k], 1.0, 0.03) << "ring " << k << ": " << figures;
}

INSTANTIATE_TEST_SUITE_P(Gallery, OneLook,
                         ::testing::Values(Look{"mandelbulb", "own"}, Look{"mandelbulb", "filled"},
                                           Look{"mandelbox", "own"}, Look{"mandelbox", "filled"},
                                           Look{"kleinian", "own"}, Look{"kleinian", "filled"}),
                         [](const auto& info) { return info.param.scene + "_" + info.param.view; });

TEST_F(RuntimeTest, sixteen_jittered_samples_give_the_picture_of_4x4_supersampling) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    const std::uint32_t n = size(96);
    FrameSettings fs;
    fs.width = fs.height = n;
    HeadlessRenderer renderer(test::shared_context(), pack, fs, StereoSettings{n, n});
    const HeadPose head = renderer.scene_camera();
    const double world_scale = pack.manifest.scene.world_scale;
    Rgba8Image plain = renderer.render(head, 0.0).left;
    Rgba8Image sixteen = render_samples(renderer, head, 0.0, 0, 16).left;
    Rgba8Image supersampled = downsample(left_eye(pack, head, world_scale, 4 * n, 4.0, 0.0), 4);
    const double p16 = test::psnr(sixteen, supersampled), p1 = test::psnr(plain, supersampled);
    std::string figures = fmt::format("bulb at {}^2 against 4x4 supersampling: 16 jittered samples {:.1f} dB, 1 spp {:.1f} dB", n, p16, p1);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GE(p16, 40.0) << figures;
    EXPECT_GT(p16, p1 + 6.0) << "the samples should move: " << figures;
    // The renderer is unjittered again: its next frame is the plain one.
    EXPECT_EQ(renderer.render(head, 0.0).left.pixels, plain.pixels);
}
