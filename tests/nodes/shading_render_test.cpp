// A frame lit by the one-sample shading nodes (fake SSS, rim, emission) on lavapipe shows, pixel
// by pixel, the colour the CPU twin computes from the same nodes and the shade pass's formula.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fmt/format.h>

#include "compiler.h"
#include "cpu/cpu_evaluator.h"
#include "frame/headless_renderer.h"
#include "pack/pack_reader.h"
#include "vk/context.h"

namespace {

const char* kLitSphere = R"({
  "format": "fractograph-graph", "version": 1, "name": "lit sphere",
  "nodes": [
    {"id": "ball", "type": "prim.sphere", "inputs": {"radius": 0.8}},
    {"id": "thin", "type": "light.fake_sss", "inputs": {"depth": 0.3, "strength": 0.8}},
    {"id": "edge", "type": "light.fake_rim", "inputs": {"eps": 0.05, "power": 2.0}},
    {"id": "glowing", "type": "light.emission", "inputs": {"color": [0.1, 0.2, 0.05]}}
  ],
  "outputs": {"distance": "ball", "sss": "thin", "rim": "edge", "emission": "glowing"},
  "scene": {"camera": {"position": [0, 0.3, 2.5], "target": [0, 0, 0], "fov_deg": 60}, "bounds": {"radius": 1.5}}
})";

constexpr std::uint32_t kSize = 64;

glm::dvec3 tonemap(glm::dvec3 c, double exposure) {
    c *= exposure;
    return glm::clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
}

struct Terms {
    glm::dvec3 base, sss, rim, emission;
    glm::dvec3 all() const { return base + sss + rim + emission; }
};

// The shade pass's formula (runtime/frame/shaders/shade.comp) in double precision.
Terms shade(const fg::CpuEvaluator& ev, const fg::SceneSettings& s, const glm::dvec3& p, const glm::dvec3& rd) {
    glm::dvec3 n = ev.normal(p);
    fg::CpuShadeInputs in;
    in.to_camera = -rd;
    in.normal = n;
    fg::CpuSurface surface = ev.surface(p, in);
    double diffuse = std::max(glm::dot(n, s.light.direction), 0.0);
    Terms t;
    t.base = surface.albedo * (s.light.ambient * surface.ao.value_or(1.0) + s.light.color * diffuse);
    t.sss = surface.sss.value_or(0.0) * s.light.sss_color * surface.albedo;
    t.rim = surface.rim.value_or(0.0) * s.light.rim_color;
    t.emission = surface.emission;
    return t;
}

TEST(ShadingRender, fake_sss_rim_and_emission_light_each_pixel_as_the_cpu_twin_does) {
    fg::Diagnostics diag;
    auto compiled = fg::compile_graph(kLitSphere, fg::NodeLibrary::builtin(), {}, diag);
    ASSERT_TRUE(compiled) << diag.format();
    auto bytes = fg::pack_bytes(*compiled);
    auto pack = fg::read_pack(bytes, diag);
    ASSERT_TRUE(pack) << diag.format();
    auto ev = fg::CpuEvaluator::create(compiled->ir, diag);
    ASSERT_TRUE(ev) << diag.format();

    fg::vk::ContextOptions options;
    options.validation = true;
    fg::vk::Context ctx(options);
    fg::FrameSettings fs;
    fs.width = fs.height = kSize;
    fs.stereo = fg::StereoMode::Naive;
    fg::StereoSettings ss;
    ss.width = ss.height = kSize;
    fg::HeadlessRenderer renderer(ctx, *pack, fs, ss);
    auto frame = renderer.render(renderer.scene_camera(), 0.0);
    const auto& view = renderer.views().left;
    const auto& scene = compiled->ir.scene;

    std::size_t hits = 0, wrong = 0, sss_visible = 0, rim_visible = 0;
    std::string first;
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x) {
            const std::size_t i = y * kSize + x;
            const double t = frame.depth_left[i];
            if (t < 0.0) continue;
            ++hits;
            glm::dvec3 rd = view.ray((x + 0.5) / kSize, (y + 0.5) / kSize);
            Terms terms = shade(*ev, scene, view.origin + rd * t, rd);
            glm::dvec3 want = tonemap(terms.all(), scene.exposure) * 255.0;
            glm::dvec3 got(frame.left.pixels[i * 4], frame.left.pixels[i * 4 + 1], frame.left.pixels[i * 4 + 2]);
            // The terms must be visible for the comparison to mean anything.
            if (glm::length(want - tonemap(terms.all() - terms.sss, scene.exposure) * 255.0) > 8.0) ++sss_visible;
            if (glm::length(want - tonemap(terms.all() - terms.rim, scene.exposure) * 255.0) > 8.0) ++rim_visible;
            glm::dvec3 diff = glm::abs(got - want);
            if (std::max({diff.x, diff.y, diff.z}) > 4.0) {
                if (!wrong)
                    first = fmt::format("pixel ({}, {}): GPU ({}, {}, {}), CPU ({:.1f}, {:.1f}, {:.1f})", x, y, got.x, got.y,
                                        got.z, want.x, want.y, want.z);
                ++wrong;
            }
        }
    EXPECT_GT(hits, kSize * kSize / 8) << "the sphere should fill part of the view";
    EXPECT_GT(sss_visible, hits / 10);
    EXPECT_GT(rim_visible, hits / 20);
    // Silhouette pixels see the normal at a grazing angle, where float and double part ways most.
    EXPECT_LE(wrong, hits / 100) << wrong << " of " << hits << " pixels differ; first " << first;
    std::printf("hits %zu wrong %zu sss %zu rim %zu\n", hits, wrong, sss_visible, rim_visible);
    EXPECT_EQ(ctx.validation_errors(), 0u);
}

}  // namespace
