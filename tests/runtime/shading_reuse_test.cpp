// Shading reuse across the eyes: with `shade_reuse`, the right eye takes the left eye's colour
// where both see the same point. The left eye is untouched, the right eye stays close to its own
// shading, and a good share of its pixels is reused. Real lavapipe, validation on.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 96;

struct Scene {
    const char* graph;
    glm::dvec3 eye, target;
};

RenderedFrame render(const Pack& pack, const Scene& scene, double reuse) {
    FrameSettings fs;
    fs.width = fs.height = kSize;
    fs.knobs["shade_reuse"] = reuse;
    HeadlessRenderer r(test::shared_context(), pack, fs, StereoSettings{kSize, kSize});
    return r.render(look_at(scene.eye, scene.target), 0.0);
}

class ShadingReuse : public RuntimeTest, public ::testing::WithParamInterface<Scene> {};

}  // namespace

// The Kleinian has fog: the colour taken is the left eye's before post effects, and the right eye
// fogs it by its own depth (taken colours left without fog fail the PSNR: 24.3 dB, tried).
INSTANTIATE_TEST_SUITE_P(Scenes, ShadingReuse,
                         ::testing::Values(Scene{"graphs/gallery/mandelbulb.json", {0.25, 0.55, 1.05}, {0.0, 0.2, 0.0}},
                                           Scene{"graphs/gallery/kleinian.json", {0.6, 0.3, 0.9}, {0.0, 0.0, 0.0}}),
                         [](const auto& info) { return info.index == 0 ? "mandelbulb" : "kleinian_with_fog"; });

TEST_P(ShadingReuse, the_right_eye_reuses_the_left_eyes_shading_where_both_see_the_same_point) {
    Pack pack = test::compile_pack(test::read_source_file(GetParam().graph));
    RenderedFrame own = render(pack, GetParam(), 0.0);
    RenderedFrame reused = render(pack, GetParam(), 1.0);
    EXPECT_EQ(own.left.pixels, reused.left.pixels) << "the left eye shades everything itself";
    EXPECT_EQ(own.depth_right, reused.depth_right) << "reuse changes colours only";
    std::size_t changed = 0;
    double se = 0.0;
    for (std::size_t i = 0; i < own.right.pixels.size(); i += 4) {
        bool differs = false;
        for (std::size_t c = 0; c < 3; ++c) {
            double d = static_cast<double>(own.right.pixels[i + c]) - reused.right.pixels[i + c];
            se += d * d;
            differs |= d != 0.0;
        }
        changed += differs;
    }
    double pixels = static_cast<double>(kSize * kSize);
    double psnr = 10.0 * std::log10(255.0 * 255.0 / (se / (3.0 * pixels)));
    RecordProperty("result", fmt::format("{:.1f}% of the right eye's pixels take the left eye's colour; PSNR {:.1f} dB",
                                         100.0 * changed / pixels, psnr));
    // Most of a filled view is seen by both eyes; the colour moves only by view-dependent terms.
    EXPECT_GT(changed / pixels, 0.3);
    EXPECT_GT(psnr, 32.0);
}
