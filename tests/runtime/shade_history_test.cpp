// Shading history (knob shade_history, shade.comp): an eye takes the previous frame's shading where
// it hits the same surface point. On a moving head the picture stays within 40 dB PSNR of shading
// every pixel while a third or more of the pixels are taken; a changed light or parameter forgets the history (the
// next frame is the one shading every pixel gives, byte for byte); and a scene whose shading
// depends on the view direction (rim light) never uses it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fmt/format.h>

#include <Imath/half.h>

#include "frame/gpu_uniforms.h"
#include "runtime_test_support.h"

using namespace fg;

namespace {

FrameSettings settings(std::uint32_t size, double history) {
    FrameSettings fs;
    fs.width = fs.height = size;
    fs.cone_levels = 4;
    fs.knobs["shade_history"] = history;
    return fs;
}

// The share of an eye's hit pixels whose colour came from the frame before (age >= 1 in the cache).
double taken_share(HeadlessRenderer& r, const std::vector<float>& depth) {
    auto cache = r.executor().download("shade_cache.left");
    std::size_t hits = 0, taken = 0;
    for (std::size_t i = 0; i < depth.size(); ++i) {
        if (depth[i] < 0.0f) continue;
        Imath::half age;   // rgba32ui, seven halves (kept_shading.glsl): the age is the fourth word's low half
        std::memcpy(&age, cache.data() + i * 16 + 12, 2);
        ++hits;
        taken += static_cast<float>(age) >= 1.0f;
    }
    return hits ? static_cast<double>(taken) / static_cast<double>(hits) : 0.0;
}

// The bulb's filled view, the head turning at 60 degrees a second (or walking at 1.4 m/s) at 90 Hz.
HeadPose head_at(int frame, bool walk) {
    double yaw = walk ? 0.0 : glm::radians(60.0 / 90.0 * frame);
    glm::dvec3 eye(walk ? 1.4 / 90.0 * frame : 0.0, 0.55, 1.45);
    return look_at(eye, eye + glm::dvec3(std::sin(-yaw), -0.55, -1.45 * std::cos(yaw)), {0.0, 1.0, 0.0});
}

class ShadeHistory : public test::RuntimeTest, public ::testing::WithParamInterface<bool> {};
class ShadeHistoryScope : public test::RuntimeTest {};

}  // namespace

TEST_P(ShadeHistory, a_moving_head_keeps_the_picture_within_40_db_of_shading_every_pixel) {
    const bool walk = GetParam();
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    // Fractal shading changes from pixel to pixel at small sizes: taking a neighbour's colour costs
    // PSNR there that it does not at a headset's resolution (96²: 37.9 dB where 256² gives 42.6).
    constexpr std::uint32_t kSize = 256;
    // Within half a cone radius: the hit tolerance (epsilon 0.5).
    HeadlessRenderer with(test::shared_context(), pack, settings(kSize, 0.5), {});
    HeadlessRenderer without(test::shared_context(), pack, settings(kSize, 0.0), {});
    double worst = 99.0, taken = 0.0;
    constexpr int kFrames = 8;
    for (int f = 0; f < kFrames; ++f) {
        RenderedFrame a = with.render(head_at(f, walk), 0.0), b = without.render(head_at(f, walk), 0.0);
        ASSERT_EQ(a.depth_left, b.depth_left) << "the march is the same with or without shading history";
        worst = std::min({worst, test::psnr(a.left, b.left), test::psnr(a.right, b.right)});
        double share = taken_share(with, a.depth_left);
        if (f == 0) EXPECT_EQ(share, 0.0) << "the first frame has no history";
        taken += share / (kFrames - 1);
    }
    std::string figures = fmt::format("{}, {}x{}: worst PSNR {:.1f} dB against shading every pixel, {:.0f} % of hit "
                                      "pixels taken from the frame before", walk ? "walk" : "look-around", kSize, kSize,
                                      worst, 100.0 * taken);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GE(worst, 40.0);
    EXPECT_GT(taken, 0.3) << "a third of the pixels should see the same point as a frame earlier";
}

INSTANTIATE_TEST_SUITE_P(Motion, ShadeHistory, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "walk" : "look_around"; });

TEST_F(ShadeHistoryScope, shading_history_is_forgotten_when_the_light_or_a_parameter_changes) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    HeadlessRenderer with(test::shared_context(), pack, settings(48, 0.5), {});
    HeadlessRenderer without(test::shared_context(), pack, settings(48, 0.0), {});
    const HeadPose head = head_at(0, false);
    // Two frames: the second took the first's colours (age 1), so the third would take them again.
    for (int f = 0; f < 2; ++f) with.render(head, 0.0);
    // A new light: the next frame must be lit by it everywhere.
    GpuScene scene = make_gpu_scene(pack.manifest.scene);
    scene.light_dir = glm::vec4(glm::normalize(glm::vec3(-0.6f, 0.7f, 0.3f)), 0.0f);
    with.executor().set_scene(scene);
    without.executor().set_scene(scene);
    EXPECT_EQ(with.render(head, 0.0).left.pixels, without.render(head, 0.0).left.pixels);
    // A new parameter value: the same.
    with.render(head, 0.0);
    ASSERT_TRUE(with.executor().set_param("hue", Constant::scalar(ValueType::Float, 0.6)));
    ASSERT_TRUE(without.executor().set_param("hue", Constant::scalar(ValueType::Float, 0.6)));
    EXPECT_EQ(with.render(head, 0.0).left.pixels, without.render(head, 0.0).left.pixels);
}

TEST_F(ShadeHistoryScope, a_foveated_graph_takes_a_new_scene_before_its_first_frame) {
    // The benchmark and the players set the scene first. Forgetting the history must not check a
    // frame that was never set (the executor refused it as "a frame without foveation").
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    FrameSettings fs = settings(48, 0.5);
    fs.lens_mask = true;
    fs.foveation = 0.4;
    HeadlessRenderer with(test::shared_context(), pack, fs, {});
    fs.knobs["shade_history"] = 0.0;
    HeadlessRenderer without(test::shared_context(), pack, fs, {});
    GpuScene scene = make_gpu_scene(pack.manifest.scene);
    scene.light_dir = glm::vec4(glm::normalize(glm::vec3(-0.6f, 0.7f, 0.3f)), 0.0f);
    ASSERT_NO_THROW(with.executor().set_scene(scene));
    without.executor().set_scene(scene);
    const HeadPose head = head_at(0, false);
    EXPECT_EQ(with.render(head, 0.0).left.pixels, without.render(head, 0.0).left.pixels);
}

TEST_F(ShadeHistoryScope, a_scene_with_view_dependent_shading_never_takes_shading_from_the_frame_before) {
    // The rim light depends on the direction the surface is seen from.
    Pack pack = test::compile_pack(R"({"format": "fractograph-graph", "version": 1, "name": "rim ball",
      "nodes": [{"id": "ball", "type": "prim.sphere", "inputs": {"radius": 0.8}},
                {"id": "rim", "type": "light.fake_rim"}],
      "outputs": {"distance": "ball", "rim": "rim.rim"}})");
    HeadlessRenderer r(test::shared_context(), pack, settings(32, 0.5), {});
    EXPECT_EQ(r.graph().find_image("shade_cache.left"), nullptr) << r.describe();
    EXPECT_EQ(r.graph().settings.knobs.at("shade_history"), 0.0);
}
