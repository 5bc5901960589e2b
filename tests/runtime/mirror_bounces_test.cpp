// Reflections that reflect again (the reflection_bounces knob) against the closed form: between two
// facing mirrors of reflectance R that glow with E, an eye ray that meets one sees E, and each
// bounce adds what the next one gives, R^k E, up to the knob's count: E (1 - R^(B+1)) / (1 - R).
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "frame/aov_images.h"
#include "aov_pixels.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 64;

class MirrorBounces : public RuntimeTest {};

}  // namespace

TEST_F(MirrorBounces, facing_mirrors_add_a_term_of_the_geometric_series_each_bounce) {
    const double reflectance = 0.5, glow = 0.2;
    // A floor at y = 0 and a ceiling at y = 1, the eye between them looking straight down: every
    // path stays between the two within the bounds.
    Pack pack = test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "facing mirrors",
      "nodes": [
        {{"id": "floor", "type": "prim.plane"}},
        {{"id": "ceiling", "type": "prim.plane", "inputs": {{"normal": [0, -1, 0], "offset": 1.0}}}},
        {{"id": "both", "type": "op.union", "inputs": {{"a": "floor.distance", "b": "ceiling.distance"}}}}
      ],
      "outputs": {{"distance": "both.distance", "albedo": [0, 0, 0], "emission": [{1}, {1}, {1}],
                  "reflection": [{0}, {0}, {0}]}},
      "scene": {{"camera": {{"position": [0, 0.5, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40}},
                "light": {{"color": [0, 0, 0], "ambient": [0, 0, 0]}}, "background": [0, 0, 0],
                "bounds": {{"radius": 50}}, "max_distance": 100}}
    }})", reflectance, glow));
    std::string figures;
    double worst = 0.0;
    for (int bounces : {1, 2, 5}) {
        FrameSettings settings = test::aov_frame(kSize);
        settings.knobs["reflection_bounces"] = bounces;
        HeadlessRenderer r(test::shared_context(), pack, settings, test::eye_at_camera(kSize));
        const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
        const double expected = glow * (1.0 - std::pow(reflectance, bounces + 1)) / (1.0 - reflectance);
        double sum = 0.0, off = 0.0;
        for (std::size_t i = 0; i < std::size_t(kSize) * kSize; ++i) {
            const double v = test::aov_half(frame, "beauty", i, 1);
            sum += v;
            off = std::max(off, std::abs(v / expected - 1.0));
        }
        worst = std::max(worst, off);
        figures += fmt::format("{}{} bounces: mean {:.5f} against {:.5f}, every pixel within {:.3f} %", figures.empty() ? "" : "; ",
                               bounces, sum / (kSize * kSize), expected, 100.0 * off);
    }
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    // Half floats hold the beauty: a part in 2048.
    EXPECT_LT(worst, 0.002) << figures;
}
