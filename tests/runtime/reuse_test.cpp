// Cross-frame reuse (cone_walk.glsl): each cone of a frame starts where the same eye's levels of
// the frame before prove it empty. It must never skip what is not proven: space uncovered since the
// last frame (behind a pillar passing in front of a wall) is marched, so the hit mask equals a render
// without reuse; the bounds it leaves hold for the pixels' whole cones; and it only runs where the
// scene cannot have changed (not for a pack whose distance reads time, not after a parameter changed).
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "frame/accuracy_metrics.h"
#include "frame/cpu_reference_tracer.h"
#include "runtime_test_support.h"

using namespace fg;

namespace {

// A pillar a little in front of a wall: moving sideways, the head sees the wall appear from behind
// the pillar's edge, space no earlier frame proved anything about.
const char* kPillar = R"({"format": "fractograph-graph", "version": 1, "name": "pillar",
  "nodes": [
    {"id": "wall_at", "type": "xform.translate", "inputs": {"offset": [0.0, 0.0, -1.0]}},
    {"id": "wall", "type": "prim.box", "inputs": {"p": "wall_at.p", "size": [3.0, 2.0, 0.1]}},
    {"id": "pillar", "type": "prim.cylinder", "inputs": {"radius": 0.15, "half_height": 2.0}},
    {"id": "both", "type": "op.union", "inputs": {"a": "wall", "b": "pillar"}}
  ],
  "outputs": {"distance": "both"},
  "scene": {"camera": {"position": [0, 0, 2.0], "target": [0, 0, 0], "fov_deg": 70}, "bounds": {"radius": 4.0}}
})";

const char* kAnimated = R"({"format": "fractograph-graph", "version": 1, "name": "pulse",
  "nodes": [
    {"id": "t", "type": "input.time"},
    {"id": "r", "type": "math.add", "inputs": {"a": 0.5, "b": "t"}},
    {"id": "ball", "type": "prim.sphere", "inputs": {"radius": "r"}}
  ],
  "outputs": {"distance": "ball"}
})";

FrameSettings settings(std::uint32_t size, bool reuse, bool count = true) {
    FrameSettings fs;
    fs.width = fs.height = size;
    fs.cone_levels = 4;
    fs.count_evaluations = count;
    fs.knobs["reuse"] = reuse ? 1.0 : 0.0;
    return fs;
}

std::size_t hits(const std::vector<float>& depth) {
    std::size_t n = 0;
    for (float t : depth) n += t >= 0.0f;
    return n;
}

class Reuse : public test::RuntimeTest {};

}  // namespace

TEST_F(Reuse, space_a_passing_pillar_uncovers_is_never_skipped) {
    Pack pack = test::compile_pack(kPillar);
    constexpr std::uint32_t kSize = 64;
    HeadlessRenderer with(test::shared_context(), pack, settings(kSize, true), {});
    HeadlessRenderer without(test::shared_context(), pack, settings(kSize, false), {});
    std::size_t differing = 0, frames = 0, reused_evaluations = 0, plain_evaluations = 0;
    for (int f = 0; f < 12; ++f) {
        // Sideways, 4 cm a frame: the pillar sweeps across the wall behind it.
        HeadPose head = look_at({-0.24 + 0.04 * f, 0.0, 2.0}, {-0.24 + 0.04 * f, 0.0, 0.0}, {0.0, 1.0, 0.0});
        RenderedFrame a = with.render(head, 0.0), b = without.render(head, 0.0);
        for (std::size_t i = 0; i < a.depth_left.size(); ++i) {
            differing += (a.depth_left[i] >= 0.0f) != (b.depth_left[i] >= 0.0f);
            differing += (a.depth_right[i] >= 0.0f) != (b.depth_right[i] >= 0.0f);
            // Where both hit, reuse lands on the same surface: within a hit threshold.
            if (a.depth_left[i] >= 0.0f && b.depth_left[i] >= 0.0f)
                EXPECT_NEAR(a.depth_left[i], b.depth_left[i], 0.01f * b.depth_left[i]) << "frame " << f << " pixel " << i;
        }
        if (f > 0) {
            reused_evaluations += a.stats.evaluations.at("march.L0");
            plain_evaluations += b.stats.evaluations.at("march.L0");
        }
        ++frames;
    }
    EXPECT_EQ(differing, 0u) << "pixels whose hit or miss changed with reuse, over " << frames << " frames";
    std::string figures = fmt::format("passing pillar, {}x{}: level-0 evaluations with reuse {} against {} without", kSize,
                                      kSize, reused_evaluations, plain_evaluations);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_LT(reused_evaluations, plain_evaluations) << "reuse should save level-0 steps on a slowly moving head";
}

TEST_F(Reuse, the_bounds_a_reused_frame_leaves_hold_for_every_ray_of_their_pixels) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    auto cpu = test::cpu_scene(pack);
    constexpr std::uint32_t kSize = 40;
    HeadlessRenderer r(test::shared_context(), pack, settings(kSize, true), {});
    RenderedFrame frame;
    // Look around the filled view: 0.7 degrees a frame, as a head turning at 60 degrees a second.
    for (int f = 0; f < 4; ++f) {
        double yaw = glm::radians(0.7 * f);
        glm::dvec3 eye(0.0, 0.55, 1.45), target = eye + glm::dvec3(std::sin(-yaw), -0.55, -1.45 * std::cos(yaw));
        frame = r.render(look_at(eye, target, {0.0, 1.0, 0.0}), 0.0);
    }
    auto atlas = r.executor().download("cone.left");
    const View& view = r.views().left;
    ReferenceSettings rs;
    rs.step_scale = 0.5 * pack.manifest.find_spec("step_scale")->value;
    rs.epsilon = 0.05;
    rs.max_steps = 4000;
    const double cone = std::tan(r.views().pixel_half_diagonal);
    std::size_t corners = 0, violations = 0;
    for (std::uint32_t level = 0; level < 4; ++level)
        for (std::uint32_t y = 0; y < kSize; y += 1u << level)
            for (std::uint32_t x = 0; x < kSize; x += 1u << level) {
                const float bound = test::atlas_cone_bound(atlas, kSize, kSize, level, x, y);
                // The rays through the corners of the level's block.
                for (double cx : {0.0, 1.0})
                    for (double cy : {0.0, 1.0}) {
                        double u = std::min<double>(kSize, x + cx * (1u << level)), v = std::min<double>(kSize, y + cy * (1u << level));
                        glm::dvec3 dir = view.ray(u / kSize, v / kSize);
                        double t = reference_trace(*cpu->evaluator, cpu->settings, view.origin, dir, cone, rs);
                        ++corners;
                        if (t >= 0.0 && bound > t + 0.1 * cone * t) ++violations;
                    }
            }
    EXPECT_GT(hits(frame.depth_left), kSize * kSize / 2);
    EXPECT_EQ(violations, 0u) << violations << " of " << corners << " corner rays meet the surface before their level's bound";
}

TEST_F(Reuse, a_scene_that_moves_by_itself_or_a_changed_parameter_reuses_nothing) {
    {
        Pack pack = test::compile_pack(kAnimated);
        EXPECT_TRUE(pack.manifest.animated);
        HeadlessRenderer r(test::shared_context(), pack, settings(32, true), {});
        EXPECT_FALSE(r.executor().graph().reuse);
        EXPECT_EQ(r.executor().graph().settings.knobs.at("reuse"), 0.0);
    }
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    EXPECT_FALSE(pack.manifest.animated);
    HeadlessRenderer with(test::shared_context(), pack, settings(48, true), {});
    HeadlessRenderer without(test::shared_context(), pack, settings(48, false), {});
    EXPECT_TRUE(with.executor().graph().reuse);
    HeadPose head = look_at({0.0, 0.55, 1.45}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
    with.render(head, 0.0);
    auto still = with.render(head, 0.0).stats;
    const auto reused = still.evaluations.at("march.L0");

    const auto plain = without.render(head, 0.0).stats.evaluations.at("march.L0");
    std::printf("still head, bulb 48x48: level-0 evaluations with reuse %u against %u without\n", unsigned(reused), unsigned(plain));
    EXPECT_LT(reused, plain) << "a still head reuses its own last frame";
    // The power changes the bulb: the next frame starts from scratch, exactly as without reuse.
    ASSERT_TRUE(with.executor().set_param("power", Constant::scalar(ValueType::Float, 7.5)));
    ASSERT_TRUE(without.executor().set_param("power", Constant::scalar(ValueType::Float, 7.5)));
    RenderedFrame a = with.render(head, 0.0), b = without.render(head, 0.0);
    EXPECT_EQ(a.stats.evaluations.at("march.L0"), b.stats.evaluations.at("march.L0"));
    EXPECT_EQ(a.depth_left, b.depth_left);
}
