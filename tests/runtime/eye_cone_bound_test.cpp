// With cross-frame reuse, level 0 of an eye records its pixel's own cone bound (for the next frame):
// the balls of the eye's plain sphere-tracing samples certify its whole pixel cone, so the bound
// holds for the rays through the pixel's corners too, and it reaches past the parent cone's bound,
// which is all an eye records without reuse (nothing reads it then, and the certificate costs a
// tenth of level 0's time on lavapipe).
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "frame/cpu_reference_tracer.h"
#include "runtime_test_support.h"

using namespace fg;

namespace {
class EyeConeBound : public test::RuntimeTest {};

constexpr std::uint32_t kSize = 48;

// The bulb's filled view at 48x48 with four levels, cross-frame reuse on or off.
struct EyeFrame {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    HeadlessRenderer renderer;
    RenderedFrame frame;
    std::vector<std::byte> atlas;   // the left eye's levels

    explicit EyeFrame(bool reuse) : renderer(test::shared_context(), pack, settings(reuse), {}) {
        frame = renderer.render(look_at({0.0, 0.55, 1.45}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}), 0.0);
        atlas = renderer.executor().download("cone.left");
    }
    static FrameSettings settings(bool reuse) {
        FrameSettings fs;
        fs.width = fs.height = kSize;
        fs.cone_levels = 4;
        fs.knobs["reuse"] = reuse ? 1.0 : 0.0;
        return fs;
    }
};
}  // namespace

TEST_F(EyeConeBound, level_0_of_an_eye_bounds_its_whole_pixel_cone_beyond_the_parent) {
    EyeFrame e(true);
    ASSERT_TRUE(e.renderer.executor().graph().reuse);
    const Pack& pack = e.pack;
    const RenderedFrame& frame = e.frame;
    const auto& atlas = e.atlas;
    HeadlessRenderer& r = e.renderer;
    auto cpu = test::cpu_scene(pack);
    const View& view = r.views().left;
    ReferenceSettings rs;
    rs.step_scale = 0.5 * pack.manifest.find_spec("step_scale")->value;   // the strict reference's rule
    rs.epsilon = 0.05;
    rs.max_steps = 4000;
    const double cone = std::tan(r.views().pixel_half_diagonal);
    std::size_t corners = 0, violations = 0, pixels = 0, beyond_parent = 0;
    double gained = 0.0;
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x) {
            if (frame.depth_left[y * kSize + x] < 0.0f) continue;
            const float bound = test::atlas_cone_bound(atlas, kSize, kSize, 0, x, y);
            const float parent = test::atlas_cone_bound(atlas, kSize, kSize, 1, x, y);
            ++pixels;
            if (bound > parent) {
                ++beyond_parent;
                gained += (bound - parent) / (cone * bound);
            }
            for (double cx : {0.0, 1.0})
                for (double cy : {0.0, 1.0}) {
                    glm::dvec3 dir = view.ray((x + cx) / kSize, (y + cy) / kSize);
                    double t = reference_trace(*cpu->evaluator, cpu->settings, view.origin, dir, cone, rs);
                    ++corners;
                    if (t >= 0.0 && bound > t + 0.1 * cone * t) ++violations;
                }
        }
    std::string figures = fmt::format("{} of {} hit pixels' bounds reach past the parent's, by {:.1f} cone radii on average",
                                      beyond_parent, pixels, beyond_parent ? gained / beyond_parent : 0.0);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GT(pixels, kSize * kSize / 2);
    EXPECT_EQ(violations, 0u) << violations << " of " << corners << " corner rays meet the surface before the bound";
    EXPECT_GT(beyond_parent, pixels * 9 / 10);
}

TEST_F(EyeConeBound, without_reuse_an_eye_records_its_parents_bound) {
    EyeFrame e(false);
    ASSERT_FALSE(e.renderer.executor().graph().reuse);
    const RenderedFrame& frame = e.frame;
    const auto& atlas = e.atlas;
    std::size_t pixels = 0, parents = 0;
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x) {
            if (frame.depth_left[y * kSize + x] < 0.0f) continue;
            ++pixels;
            if (test::atlas_cone_bound(atlas, kSize, kSize, 0, x, y) == test::atlas_cone_bound(atlas, kSize, kSize, 1, x, y))
                ++parents;
        }
    EXPECT_GT(pixels, kSize * kSize / 2);
    EXPECT_EQ(parents, pixels);
}
