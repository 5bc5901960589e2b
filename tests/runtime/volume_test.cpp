// A medium drawn as nodes (the graph's volume outputs) on real frames (the beauty AOV, linear): a
// uniform medium gives Beer-Lambert's transmittance before a wall and before the sky; a ball of
// medium gives each ray its chord's optical depth; and iteration fog, read from a Mandelbulb's
// escape output, gives what the CPU twin integrates along each ray.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "offline/jittered_samples.h"
#include "aov_pixels.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 64;

class Volume : public RuntimeTest {};

double beauty(const RenderedFrame& f, std::size_t pixel, int channel) { return test::aov_half(f, "beauty", pixel, channel); }

}  // namespace

TEST_F(Volume, a_uniform_medium_passes_light_by_beer_lambert_and_gives_its_colour_for_the_rest) {
    // A medium of density 0.4 and red 0.5 fills the bounds (radius 3 about the camera). The right
    // of the view is a wall at z = -2 that emits 1; the left sees a white sky. A pixel shows
    // 1 T + 0.5 (1 - T), T = e^(-0.4 t): t the way to the wall, or 3 to the bounds' edge.
    const double density = 0.4, red = 0.5, radius = 3.0;
    Pack pack = test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "uniform medium",
      "nodes": [{{"id": "at", "type": "xform.translate", "inputs": {{"offset": [1.5, 0, -2.5]}}}},
                {{"id": "wall", "type": "prim.box", "inputs": {{"p": "at.p", "size": [1.5, 3, 0.5]}}}}],
      "outputs": {{"distance": "wall.distance", "albedo": [0, 0, 0], "emission": [1, 1, 1],
                  "volume_density": {}, "volume_color": [{}, 0.25, 1.0]}},
      "scene": {{"camera": {{"position": [0, 0, 0], "target": [0, 0, -1], "fov_deg": 60}},
                "light": {{"color": [0, 0, 0], "ambient": [0, 0, 0]}},
                "background": [1, 1, 1], "bounds": {{"radius": {}}}, "max_distance": 20}}
    }})", density, red, radius));
    ASSERT_TRUE(pack.manifest.effects.has(Effect::Volume));
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame f = r.render(r.scene_camera(), 0.0);
    double worst[2] = {0.0, 0.0};
    int counted[2] = {0, 0};
    for (std::uint32_t y = 1; y < kSize; y += 3)
        for (std::uint32_t x = 1; x < kSize; x += 3) {
            const glm::dvec3 d = r.views().left.ray((x + 0.5) / kSize, (y + 0.5) / kSize);
            const double to_wall = 2.0 / -d.z, at_x = to_wall * d.x;
            if (std::abs(at_x) < 0.1) continue;   // the wall's edge
            const bool wall = at_x > 0.0;
            // The march stops within a fraction of the pixel's cone before the wall: the way there
            // is the hit's depth (along the view axis, -z).
            const double to_hit = test::aov_position(f, std::size_t(y) * kSize + x).w / -d.z;
            if (wall) EXPECT_NEAR(to_hit, to_wall, 0.05);
            const double expected = std::exp(-density * (wall ? to_hit : radius));
            const double seen = (beauty(f, std::size_t(y) * kSize + x, 0) - red) / (1.0 - red);
            worst[wall] = std::max(worst[wall], std::abs(seen / expected - 1.0));
            ++counted[wall];
        }
    const std::string figures = fmt::format("the transmittance at most {:.3f} % from Beer-Lambert's before the sky ({} rays) "
                                            "and {:.3f} % before the wall ({} rays)",
                                            100.0 * worst[0], counted[0], 100.0 * worst[1], counted[1]);
    RecordProperty("uniform", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GT(counted[0], 50);
    EXPECT_GT(counted[1], 50);
    EXPECT_LT(std::max(worst[0], worst[1]), 0.005) << figures;
}

TEST_F(Volume, a_ball_of_medium_gives_each_ray_its_chords_optical_depth_as_samples_accumulate) {
    // Density 1.5 inside a ball of radius 1 at (0, 0, -3), colour 1, before a black sky: a ray whose
    // chord through the ball is c shows 1 - e^(-1.5 c). The medium jumps at the ball's edge, which
    // a segment's one point cannot place: a frame dithers there, samples converge.
    const double density = 1.5, radius = 1.0, depth = 3.0;
    Pack pack = test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "ball of medium",
      "nodes": [{{"id": "behind", "type": "xform.translate", "inputs": {{"offset": [0, 0, 20]}}}},
                {{"id": "far", "type": "prim.sphere", "inputs": {{"p": "behind.p", "radius": 0.1}}}},
                {{"id": "at", "type": "xform.translate", "inputs": {{"offset": [0, 0, -{}]}}}},
                {{"id": "from_centre", "type": "math.length", "inputs": {{"v": "at.p"}}}},
                {{"id": "inside", "type": "math.step", "inputs": {{"edge": "from_centre", "x": {}}}}},
                {{"id": "medium", "type": "math.scale", "inputs": {{"v": "inside", "s": {}}}}}],
      "outputs": {{"distance": "far.distance", "volume_density": "medium"}},
      "scene": {{"camera": {{"position": [0, 0, 0], "target": [0, 0, -1], "fov_deg": 50}},
                "light": {{"color": [0, 0, 0], "ambient": [0, 0, 0]}},
                "background": [0, 0, 0], "bounds": {{"radius": 6}}, "max_distance": 20}}
    }})", depth, radius, density));
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
    const View view = r.views().left;   // unjittered: the samples move it
    const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 64);
    const glm::dvec3 centre(0.0, 0.0, -depth);
    double frame_worst = 0.0, sampled_worst = 0.0, frame_sum = 0.0, sampled_sum = 0.0, exact_sum = 0.0;
    int rays = 0;
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x) {
            const glm::dvec3 d = view.ray((x + 0.5) / kSize, (y + 0.5) / kSize);
            const double along = glm::dot(centre, d), miss2 = glm::dot(centre, centre) - along * along;
            // Well inside the ball's outline: a pixel's jitter keeps to one side of the edge.
            if (miss2 > 0.5 * radius * radius) continue;
            const double expected = 1.0 - std::exp(-density * 2.0 * std::sqrt(radius * radius - miss2));
            const std::size_t i = std::size_t(y) * kSize + x;
            frame_worst = std::max(frame_worst, std::abs(beauty(frame, i, 0) / expected - 1.0));
            sampled_worst = std::max(sampled_worst, std::abs(beauty(sampled, i, 0) / expected - 1.0));
            frame_sum += beauty(frame, i, 0), sampled_sum += beauty(sampled, i, 0), exact_sum += expected;
            ++rays;
        }
    const std::string figures = fmt::format(
        "{} rays through the ball: a frame at most {:.2f} % from 1 - e^(-density chord) ({:+.3f} % summed), 64 samples at "
        "most {:.2f} % ({:+.3f} % summed)",
        rays, 100.0 * frame_worst, 100.0 * (frame_sum / exact_sum - 1.0), 100.0 * sampled_worst,
        100.0 * (sampled_sum / exact_sum - 1.0));
    RecordProperty("ball", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GT(rays, 300);
    EXPECT_LT(sampled_worst, 0.02) << figures;
    EXPECT_NEAR(sampled_sum / exact_sum, 1.0, 0.005) << figures;
    EXPECT_NEAR(frame_sum / exact_sum, 1.0, 0.03) << figures;
}

TEST_F(Volume, iteration_fog_from_a_fractals_escape_converges_to_what_the_cpu_twin_integrates_along_each_ray) {
    // A power 8 Mandelbulb in iteration fog: rays that pass it gather the fog's colour, which the CPU
    // twin (double precision) integrates along each ray over 4000 intervals from the graph's own
    // volume outputs. A segment's one point makes its absorption a little short where the fog
    // thickens within it (1 - e^(-x) is concave): the frame's sum comes closer as volume_steps grows.
    const std::string graph = R"({
      "format": "fractograph-graph", "version": 1, "name": "bulb in iteration fog",
      "nodes": [{"id": "bulb", "type": "fractal.mandelbulb", "inputs": {"power": 8.0, "iterations": 8, "bailout": 2.0}},
                {"id": "fog", "type": "light.iteration_fog",
                 "inputs": {"escape": "bulb.escape", "start": 0.5, "full": 2.5, "opacity": 4.0,
                            "outer": [0.2, 0.4, 1.0], "inner": [1.0, 0.6, 0.2]}}],
      "outputs": {"distance": "bulb.distance", "albedo": [0, 0, 0], "volume_density": "fog.density", "volume_color": "fog.color"},
      "scene": {"camera": {"position": [0, 0, 2.4], "target": [0, 0, 0], "fov_deg": 70},
                "light": {"color": [0, 0, 0], "ambient": [0, 0, 0]},
                "background": [0, 0, 0], "bounds": {"radius": 1.5}, "max_distance": 10}
    })";
    Pack pack = test::compile_pack(graph);
    auto cpu = test::cpu_scene(pack);
    ASSERT_TRUE(cpu && cpu->evaluator);
    const CpuEvaluator& twin = *cpu->evaluator;
    std::vector<double> sums;
    std::string figures;
    for (int steps : {32, 256}) {
        FrameSettings settings = test::aov_frame(kSize);
        settings.knobs["volume_steps"] = steps;
        HeadlessRenderer r(test::shared_context(), pack, settings, test::eye_at_camera(kSize));
        const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
        const glm::dvec3 eye(0.0, 0.0, 2.4);
        double gpu_sum = 0.0, cpu_sum = 0.0;
        int rays = 0;
        for (std::uint32_t y = 1; y < kSize; y += 2)
            for (std::uint32_t x = 1; x < kSize; x += 2) {
                const std::size_t i = std::size_t(y) * kSize + x;
                if (std::isfinite(test::aov_position(frame, i).w)) continue;   // the fog before a hit depends on the hit
                const glm::dvec3 d = r.views().left.ray((x + 0.5) / kSize, (y + 0.5) / kSize);
                const double along = -glm::dot(eye, d), miss2 = glm::dot(eye, eye) - along * along;
                if (miss2 >= 1.5 * 1.5) continue;
                const double half = std::sqrt(1.5 * 1.5 - miss2), from = along - half, length = 2.0 * half;
                const int intervals = 4000;
                double through = 1.0, red = 0.0;
                for (int k = 0; k < intervals; ++k) {
                    const glm::dvec3 p = eye + d * (from + (k + 0.5) * length / intervals);
                    const double absorbed = 1.0 - std::exp(-twin.output("volume_density", p, {})->f() * length / intervals);
                    red += through * absorbed * twin.output("volume_color", p, {})->v3().x;
                    through *= 1.0 - absorbed;
                }
                gpu_sum += beauty(frame, i, 0), cpu_sum += red;
                ++rays;
            }
        sums.push_back(gpu_sum / cpu_sum - 1.0);
        figures += fmt::format("{}{} steps: {:+.2f} %", figures.empty() ? "" : ", ", steps, 100.0 * sums.back());
        EXPECT_GT(rays, 200);
    }
    figures = "the fog's red summed over the rays past the bulb, against the CPU twin's integral: " + figures;
    RecordProperty("iteration_fog", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_LT(std::abs(sums[0]), 0.08) << figures;
    EXPECT_LT(std::abs(sums[1]), 0.01) << figures;
    EXPECT_LT(std::abs(sums[1]), std::abs(sums[0])) << figures;
}
