// Fog against Beer-Lambert, on real frames (the beauty AOV, linear): before a white background and
// with black fog, a pixel shows the transmittance along its ray to the far limit. Homogeneous fog is
// exp(-density t); height fog's density falls exponentially with height, and its transmittance is
// compared with the optical depth integrated numerically along each pixel's ray.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <fmt/format.h>

#include "frame/aov_images.h"
#include "offline/jittered_samples.h"
#include "aov_pixels.h"
#include "lat_long_exr.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 64;

double beauty_red(const RenderedFrame& f, std::size_t pixel) { return test::aov_half(f, "beauty", pixel, 0); }

// The integral of f over [0, length] by Simpson's rule over n (even) intervals.
template <class F>
double simpson(F f, double length, int n) {
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) sum += (i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0) * f(length * i / n);
    return sum * length / (3.0 * n);
}

class Fog : public RuntimeTest {};

}  // namespace

TEST_F(Fog, transmittance_along_each_ray_is_beer_lambert_for_homogeneous_and_height_fog) {
    const double density = 0.15, far = 10.0, falloff = 0.5, base = 0.25;
    const glm::dvec3 eye(0.0, 1.0, 0.0);
    for (const bool height : {false, true}) {
        // Nothing in view: one small ball behind the camera.
        Pack pack = test::compile_pack(fmt::format(R"({{
          "format": "fractograph-graph", "version": 1, "name": "fog",
          "nodes": [{{"id": "at", "type": "xform.translate", "inputs": {{"offset": [0, 0, 20]}}}},
                    {{"id": "ball", "type": "prim.sphere", "inputs": {{"p": "at.p", "radius": 0.1}}}}],
          "outputs": {{"distance": "ball.distance"}},
          "scene": {{"camera": {{"position": [0, 1, 0], "target": [0, 1.2, -1], "fov_deg": 80}},
                    "background": [1, 1, 1], "bounds": {{"radius": 50}}, "max_distance": {},
                    "fog": {{"color": [0, 0, 0], "density": {}{}}}}}
        }})", far, density, height ? fmt::format(R"(, "height_falloff": {}, "height": {})", falloff, base) : ""));
        HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
        const RenderedFrame f = r.render(r.scene_camera(), 0.0);
        const View& view = r.views().left;
        double worst = 0.0, lowest = 1.0;
        for (std::uint32_t y = 0; y < kSize; y += 3)
            for (std::uint32_t x = 0; x < kSize; x += 3) {
                const glm::dvec3 d = view.ray((x + 0.5) / kSize, (y + 0.5) / kSize);
                // The optical depth by Simpson's rule over 2000 intervals.
                const double depth = simpson(
                    [&](double s) { return height ? density * std::exp(-falloff * (eye.y + d.y * s - base)) : density; }, far, 2000);
                const double expected = std::exp(-depth);
                if (expected < 0.05) continue;   // too dark for the beauty's half floats to say 0.5 %
                lowest = std::min(lowest, expected);
                worst = std::max(worst, std::abs(beauty_red(f, std::size_t(y) * kSize + x) / expected - 1.0));
            }
        const std::string figures = fmt::format("{} fog: the transmittance at most {:.3f} % from Beer-Lambert's "
                                                "(down to {:.3f})", height ? "height" : "homogeneous", 100.0 * worst, lowest);
        RecordProperty(height ? "height" : "homogeneous", figures);
        std::printf("%s\n", figures.c_str());
        EXPECT_LT(worst, 0.005) << figures;
        EXPECT_LT(lowest, 0.5) << "the fog is too thin to test: " << figures;
    }
}

TEST_F(Fog, the_light_it_scatters_follows_the_phase_and_samples_shadow_it_into_shafts) {
    // Black fog of density 0.1 before a black sky, scattering the main light (colour 1): a ray to
    // the far limit 10 gathers share * phase * (1 - e^-1). Looking down -z with the light straight
    // up, a slab above the left half of the view (x < 0) shades every point of the rays that lean
    // left: sampled, they gather nothing and the others all of it; a frame does not shadow.
    const double density = 0.1, far = 10.0, share = 1.0;
    auto scene = [&](const glm::dvec3& light, double anisotropy) {
        return test::compile_pack(fmt::format(R"({{
          "format": "fractograph-graph", "version": 1, "name": "shafts",
          "nodes": [{{"id": "at", "type": "xform.translate", "inputs": {{"offset": [-5, 2, -5]}}}},
                    {{"id": "slab", "type": "prim.box", "inputs": {{"p": "at.p", "size": [5, 0.1, 10]}}}}],
          "outputs": {{"distance": "slab.distance"}},
          "scene": {{"camera": {{"position": [0, 0, 0], "target": [0, 0, -1], "fov_deg": 40}},
                    "light": {{"direction": [{}, {}, {}], "color": [1, 1, 1], "ambient": [0, 0, 0]}},
                    "background": [0, 0, 0], "bounds": {{"radius": 50}}, "max_distance": {},
                    "fog": {{"color": [0, 0, 0], "density": {}, "scatter": {}, "anisotropy": {}}}}}
        }})", light.x, light.y, light.z, far, density, share, anisotropy));
    };
    const double opaque = 1.0 - std::exp(-density * far);
    auto phase = [](double g, double cos_angle) {
        return (1.0 - g * g) / (4.0 * glm::pi<double>() * std::pow(1.0 + g * g - 2.0 * g * cos_angle, 1.5));
    };
    // A frame, forward-scattering fog, the light ahead and up: each ray by its angle to the light.
    const glm::dvec3 ahead = glm::normalize(glm::dvec3(0.0, 0.6, -0.8));
    {
        Pack pack = scene(ahead, 0.6);
        HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
        const RenderedFrame f = r.render(r.scene_camera(), 0.0);
        double worst = 0.0;
        int checked = 0;
        for (std::uint32_t y = kSize / 2 - 8; y < kSize / 2 + 8; y += 2)
            for (std::uint32_t x = 0; x < kSize; x += 3) {
                const glm::dvec3 d = r.views().left.ray((x + 0.5) / kSize, (y + 0.5) / kSize);
                const double expected = share * phase(0.6, glm::dot(ahead, d)) * opaque;
                worst = std::max(worst, std::abs(beauty_red(f, std::size_t(y) * kSize + x) / expected - 1.0));
                ++checked;
            }
        const std::string figures = fmt::format("a frame of forward-scattering fog (g 0.6): {} rays at most {:.3f} % from "
                                                "share x phase x (1 - T)", checked, 100.0 * worst);
        RecordProperty("phase", figures);
        std::printf("%s\n", figures.c_str());
        EXPECT_LT(worst, 0.01) << figures;
    }
    // The light straight up, the slab over the left: samples shadow, a frame does not.
    Pack pack = scene({0.0, 1.0, 0.0}, 0.0);
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
    const View view = r.views().left;   // unjittered: the samples move it
    const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 16);
    const double lit = share * phase(0.0, 0.0) * opaque;
    double left_frame = 0.0, left_sampled = 0.0, right_sampled = 0.0;
    int left = 0, right = 0;
    for (std::uint32_t y = kSize / 2 - 8; y < kSize / 2 + 8; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x) {
            const glm::dvec3 d = view.ray((x + 0.5) / kSize, (y + 0.5) / kSize);
            const std::size_t i = std::size_t(y) * kSize + x;
            // Away from the slab's edge by more than the pixel's cone, which shadow rays hit by.
            if (d.x < -0.1) left_frame += beauty_red(frame, i), left_sampled += beauty_red(sampled, i), ++left;
            if (d.x > 0.1) right_sampled += beauty_red(sampled, i), ++right;
        }
    left_frame /= left, left_sampled /= left, right_sampled /= right;
    const std::string figures = fmt::format(
        "light straight up, a slab over the left: 16 samples gather {:.5f} right and {:.5f} left (lit: {:.5f}); a "
        "frame {:.5f} left", right_sampled, left_sampled, lit, left_frame);
    RecordProperty("shafts", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_NEAR(right_sampled / lit, 1.0, 0.01) << figures;
    EXPECT_LT(left_sampled, 0.01 * lit) << figures;
    EXPECT_NEAR(left_frame / lit, 1.0, 0.01) << figures;
}

TEST_F(Fog, an_auxiliary_point_light_scatters_by_the_integral_along_each_ray) {
    // Black fog before a black sky, the main light off, a point light of intensity 2 at (0.8, 0, -3)
    // beside the view: each ray gathers the integral of share * density * T(s) * phase * I / d(s)^2
    // over its length, here by Simpson's rule over 4000 intervals. A frame takes 16 points evenly
    // spread in the angle seen from the light; 64 samples one point each, and a march to the light
    // that nothing blocks.
    const double density = 0.2, far = 8.0, share = 1.5, intensity = 2.0, g = 0.3;
    const glm::dvec3 light(0.8, 0.0, -3.0);
    Pack pack = test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "lamp in fog",
      "nodes": [{{"id": "at", "type": "xform.translate", "inputs": {{"offset": [0, 0, 20]}}}},
                {{"id": "ball", "type": "prim.sphere", "inputs": {{"p": "at.p", "radius": 0.1}}}}],
      "outputs": {{"distance": "ball.distance"}},
      "scene": {{"camera": {{"position": [0, 0, 0], "target": [0, 0, -1], "fov_deg": 60}},
                "light": {{"color": [0, 0, 0], "ambient": [0, 0, 0],
                          "auxiliary": [{{"position": [{}, {}, {}], "color": {}}}]}},
                "background": [0, 0, 0], "bounds": {{"radius": 50}}, "max_distance": {},
                "fog": {{"color": [0, 0, 0], "density": {}, "scatter": {}, "anisotropy": {}}}}}
    }})", light.x, light.y, light.z, intensity, far, density, share, g));
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
    const View view = r.views().left;   // unjittered: the samples move it
    const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 64);
    auto phase = [&](double cos_angle) {
        return (1.0 - g * g) / (4.0 * glm::pi<double>() * std::pow(1.0 + g * g - 2.0 * g * cos_angle, 1.5));
    };
    double frame_worst = 0.0, frame_sum = 0.0, sampled_sum = 0.0, exact_sum = 0.0;
    int checked = 0;
    for (std::uint32_t y = 0; y < kSize; y += 3)
        for (std::uint32_t x = 0; x < kSize; x += 3) {
            const glm::dvec3 d = view.ray((x + 0.5) / kSize, (y + 0.5) / kSize);
            const double exact = share * simpson([&](double s) {
                const glm::dvec3 to_light = light - d * s;
                const double d2 = glm::dot(to_light, to_light);
                return density * std::exp(-density * s) * phase(glm::dot(to_light, d) / std::sqrt(d2)) * intensity / d2;
            }, far, 4000);
            const std::size_t i = std::size_t(y) * kSize + x;
            frame_worst = std::max(frame_worst, std::abs(beauty_red(frame, i) / exact - 1.0));
            frame_sum += beauty_red(frame, i), sampled_sum += beauty_red(sampled, i), exact_sum += exact;
            ++checked;
        }
    const std::string figures = fmt::format(
        "{} rays past a point light in fog: a frame at most {:.2f} % from the integral ({:+.2f} % summed over the rays), "
        "64 samples {:+.2f} % summed",
        checked, 100.0 * frame_worst, 100.0 * (frame_sum / exact_sum - 1.0), 100.0 * (sampled_sum / exact_sum - 1.0));
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_LT(frame_worst, 0.02) << figures;
    EXPECT_NEAR(sampled_sum / exact_sum, 1.0, 0.01) << figures;
}

TEST_F(Fog, the_environment_scatters_by_the_phase_averaged_sky) {
    // Fog of density 0.2 lit by the environment alone, the view up into the sky (nothing in it: a
    // small ball far below): a ray to the far limit 10 sees the sky through T = e^-2 and gathers
    // share * (1 - T) * the sky's radiance averaged by the phase. A uniform sky of 1 gives 1
    // whatever the anisotropy (g 0.6 here); a sky lit only above the horizon gives 1/2 to isotropic
    // fog (g 0) in every direction. A frame takes the harmonics, 64 samples one direction each.
    const double density = 0.2, share = 1.5, far = 10.0;
    const double transmittance = std::exp(-density * far);
    auto render = [&](const std::string& sky, double g, double expected) {
        Pack pack = test::compile_pack(fmt::format(R"({{
          "format": "fractograph-graph", "version": 1, "name": "sky in fog",
          "nodes": [{{"id": "at", "type": "xform.translate", "inputs": {{"offset": [0, -30, 0]}}}},
                    {{"id": "ball", "type": "prim.sphere", "inputs": {{"p": "at.p", "radius": 0.1}}}}],
          "outputs": {{"distance": "ball.distance"}},
          "scene": {{"camera": {{"position": [0, 0, 0], "target": [0, 0.6, -1], "fov_deg": 40}},
                    "light": {{"color": [0, 0, 0], "ambient": [0, 0, 0]}}, "albedo": [0, 0, 0],
                    "environment": {}, "bounds": {{"radius": 50}}, "max_distance": {},
                    "fog": {{"color": [0, 0, 0], "density": {}, "scatter": {}, "anisotropy": {}}}}}
        }})", sky, far, density, share, g));
        HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
        const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
        const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 64);
        // What the fog scattered: the beauty less the sky seen through it (1 in every pixel here).
        auto scattered = [&](const RenderedFrame& f, std::size_t i) { return (beauty_red(f, i) - transmittance) / (share * (1.0 - transmittance)); };
        double frame_worst = 0.0, sampled_sum = 0.0;
        int n = 0;
        for (std::size_t i = 0; i < std::size_t(kSize) * kSize; i += 7, ++n) {
            frame_worst = std::max(frame_worst, std::abs(scattered(frame, i) / expected - 1.0));
            sampled_sum += scattered(sampled, i);
        }
        return std::make_pair(frame_worst, sampled_sum / (n * expected));
    };
    const std::string half_sky =
        test::write_lat_long_exr("half", 64, 32, [](double, double v) { return glm::dvec3(v < 0.5 ? 1.0 : 0.0); });
    const auto [uniform_frame, uniform_sampled] = render(R"({"color": [1, 1, 1]})", 0.6, 1.0);
    const auto [half_frame, half_sampled] = render(fmt::format(R"({{"image": "{}"}})", half_sky), 0.0, 0.5);
    std::filesystem::remove(half_sky);
    const std::string figures = fmt::format(
        "a uniform sky, g 0.6: a frame at most {:.3f} % from share (1 - T), 64 samples {:+.2f} % summed; the upper half "
        "of the sky, g 0: a frame at most {:.3f} % from share (1 - T) / 2, 64 samples {:+.2f} %",
        100.0 * uniform_frame, 100.0 * (uniform_sampled - 1.0), 100.0 * half_frame, 100.0 * (half_sampled - 1.0));
    RecordProperty("environment", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_LT(uniform_frame, 0.005) << figures;
    EXPECT_NEAR(uniform_sampled, 1.0, 0.02) << figures;
    EXPECT_LT(half_frame, 0.01) << figures;
    EXPECT_NEAR(half_sampled, 1.0, 0.02) << figures;
}
