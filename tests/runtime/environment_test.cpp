// Environment light (scene.environment) against closed-form answers, on real frames (the beauty
// AOV, linear): a white diffuse sphere inside a uniform sky returns its albedo (the furnace test),
// in a frame and as the mean of samples; a sky lit only within 60 degrees of the zenith lights a
// plane by the analytic integral, sampled, and by the order-2 harmonics' own closed form in a frame;
// the background shows the image where a panorama of fgplay's would put it, turned as asked.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
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

constexpr std::uint32_t kSize = 96;
constexpr double kPi = std::numbers::pi;

// One body (`distance` and its nodes) lit by the environment alone, albedo 0.8.
Pack lit_by_sky(const std::string& nodes, const std::string& distance, const std::string& camera, const std::string& environment) {
    return test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "lit by the sky",
      "nodes": [{0}],
      "outputs": {{"distance": "{1}"}},
      "scene": {{"camera": {2}, "light": {{"color": [0, 0, 0], "ambient": [0, 0, 0]}}, "albedo": [0.8, 0.8, 0.8],
                "environment": {3}, "bounds": {{"radius": 50}}, "max_distance": 100}}
    }})", nodes, distance, camera, environment));
}

class Environment : public RuntimeTest {};

}  // namespace

TEST_F(Environment, a_white_diffuse_sphere_in_a_uniform_sky_returns_its_albedo) {
    Pack pack = lit_by_sky(R"({"id": "ball", "type": "prim.sphere", "inputs": {"radius": 1.0}})", "ball.distance",
                           R"({"position": [0, 0, 3], "target": [0, 0, 0], "fov_deg": 50})",
                           R"({"color": [1.0, 1.0, 1.0]})");
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
    const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 64);
    double frame_worst = 0.0, sampled_sum = 0.0, sky_worst = 0.0;
    std::size_t ball = 0;
    for (std::size_t i = 0; i < kSize * kSize; ++i) {
        if (!test::aov_hit(frame, i)) {
            sky_worst = std::max(sky_worst, std::abs(test::aov_beauty(frame, i, 1) - 1.0));
            continue;
        }
        ++ball;
        frame_worst = std::max(frame_worst, std::abs(test::aov_beauty(frame, i, 1) / 0.8 - 1.0));
        sampled_sum += test::aov_beauty(sampled, i, 1);
    }
    const double sampled_mean = sampled_sum / std::max<std::size_t>(ball, 1);
    const std::string figures = fmt::format(
        "{} pixels of the ball: a frame at most {:.3f} % from the albedo 0.8; the mean of 64 samples {:.4f} ({:+.3f} %); "
        "the sky at most {:.4f} from 1",
        ball, 100.0 * frame_worst, sampled_mean, 100.0 * (sampled_mean / 0.8 - 1.0), sky_worst);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    ASSERT_GT(ball, 2000u) << figures;
    EXPECT_LT(frame_worst, 0.01) << figures;
    EXPECT_NEAR(sampled_mean, 0.8, 0.008) << figures;
    EXPECT_LT(sky_worst, 0.002) << figures;
}

TEST_F(Environment, a_sky_bright_near_the_zenith_lights_a_plane_as_the_integral_says) {
    // Radiance 2 within 60 degrees of the zenith, black below: a plane facing up receives
    // E = pi L sin^2(60), and reflects albedo E / pi. The harmonics' truncation has its own closed
    // form: the cap's order-0, 1 and 2 coefficients, each times its share of the cosine lobe.
    const double radiance = 2.0, cap = kPi / 3.0;
    const std::string sky =
        test::write_lat_long_exr("cap", 240, 120, [&](double, double v) { return glm::dvec3(v * kPi < cap ? radiance : 0.0); });
    Pack pack = lit_by_sky(R"({"id": "ground", "type": "prim.plane"})", "ground.distance",
                           R"({"position": [0, 2, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 60})",
                           fmt::format(R"({{"image": "{}"}})", sky));
    std::filesystem::remove(sky);
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
    const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 64);
    double frame_sum = 0.0, sampled_sum = 0.0;
    std::size_t plane = 0;
    for (std::size_t i = 0; i < kSize * kSize; ++i) {
        if (!test::aov_hit(frame, i)) continue;
        ++plane;
        frame_sum += test::aov_beauty(frame, i, 0);
        sampled_sum += test::aov_beauty(sampled, i, 0);
    }
    const double exact = 0.8 * radiance * std::sin(cap) * std::sin(cap);
    const double c = std::cos(cap), s2 = std::sin(cap) * std::sin(cap);
    const double y0 = 0.282095, y1 = 0.488603, y2 = 0.315392;
    const double harmonics = 0.8 * radiance / kPi *
                             (kPi * y0 * y0 * 2.0 * kPi * (1.0 - c) + 2.0 * kPi / 3.0 * y1 * y1 * kPi * s2 +
                              kPi / 4.0 * 2.0 * y2 * y2 * 2.0 * kPi * c * s2);
    const double frame_mean = frame_sum / std::max<std::size_t>(plane, 1), sampled_mean = sampled_sum / std::max<std::size_t>(plane, 1);
    const std::string figures = fmt::format(
        "{} pixels of the plane: 64 samples {:.4f} against the integral {:.4f} ({:+.3f} %); a frame {:.4f} against the "
        "harmonics' closed form {:.4f} ({:+.3f} %), which is {:+.2f} % from the integral",
        plane, sampled_mean, exact, 100.0 * (sampled_mean / exact - 1.0), frame_mean, harmonics,
        100.0 * (frame_mean / harmonics - 1.0), 100.0 * (harmonics / exact - 1.0));
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    ASSERT_EQ(plane, std::size_t(kSize) * kSize) << figures;
    EXPECT_NEAR(sampled_mean / exact, 1.0, 0.01) << figures;
    EXPECT_NEAR(frame_mean / harmonics, 1.0, 0.005) << figures;
}

TEST_F(Environment, the_background_shows_the_image_where_a_panorama_puts_it_turned_as_asked) {
    // Red is the image's u, green its v: each background pixel must read the (u, v) its direction
    // maps to, u = 0.5 looking down -z and growing towards +x, v = 0 straight up; turned 90 degrees
    // counter-clockwise from above, what was towards +x is seen down -z.
    const std::string sky = test::write_lat_long_exr("uv", 512, 256, [](double u, double v) { return glm::dvec3(u, v, 0.0); });
    for (double turn : {0.0, 90.0}) {
        // Nothing in view: one small ball behind the camera.
        Pack pack = lit_by_sky(R"({"id": "at", "type": "xform.translate", "inputs": {"offset": [0, 0, 20]}},
                                  {"id": "ball", "type": "prim.sphere", "inputs": {"p": "at.p", "radius": 0.1}})",
                               "ball.distance", R"({"position": [0, 0, 0], "target": [0, 0.3, -1], "fov_deg": 80})",
                               fmt::format(R"({{"image": "{}", "rotation_deg": {}}})", sky, turn));
        HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
        const RenderedFrame f = r.render(r.scene_camera(), 0.0);
        const View& view = r.views().left;
        double worst = 0.0;
        for (std::uint32_t y = 0; y < kSize; y += 5)
            for (std::uint32_t x = 0; x < kSize; x += 5) {
                const glm::dvec3 d = view.ray((x + 0.5) / kSize, (y + 0.5) / kSize);
                const double a = glm::radians(turn);
                const glm::dvec3 l(std::cos(a) * d.x - std::sin(a) * d.z, d.y, std::sin(a) * d.x + std::cos(a) * d.z);
                const double u = 0.5 + std::atan2(l.x, -l.z) / (2.0 * kPi), v = std::acos(l.y) / kPi;
                const std::size_t i = std::size_t(y) * kSize + x;
                worst = std::max({worst, std::abs(test::aov_beauty(f, i, 0) - u), std::abs(test::aov_beauty(f, i, 1) - v)});
            }
        const std::string figures = fmt::format("turned {} degrees: the background's (u, v) at most {:.5f} from the "
                                                "direction's (a texel is {:.5f})", turn, worst, 1.0 / 512);
        RecordProperty(fmt::format("figures_{}", turn), figures);
        std::printf("%s\n", figures.c_str());
        EXPECT_LT(worst, 1.0 / 512) << figures;
    }
    std::filesystem::remove(sky);
}

TEST_F(Environment, a_sky_split_into_halves_lights_each_side_of_a_sphere_by_its_own_half) {
    // Green over the half of the sky towards the camera (+z), red over the other: the point of the
    // ball facing the camera sees all green and no red, in a frame (the harmonics hold a half-space
    // exactly at its pole) and sampled.
    const std::string sky = test::write_lat_long_exr("halves", 256, 128, [](double u, double) {
        return u >= 0.25 && u < 0.75 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    });
    Pack pack = lit_by_sky(R"({"id": "ball", "type": "prim.sphere", "inputs": {"radius": 1.0}})", "ball.distance",
                           R"({"position": [0, 0, 3], "target": [0, 0, 0], "fov_deg": 50})",
                           fmt::format(R"({{"image": "{}"}})", sky));
    std::filesystem::remove(sky);
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
    const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 64);
    glm::dvec3 in_frame(0.0), in_samples(0.0);
    int n = 0;
    for (std::uint32_t y = kSize / 2 - 2; y < kSize / 2 + 2; ++y)
        for (std::uint32_t x = kSize / 2 - 2; x < kSize / 2 + 2; ++x, ++n) {
            const std::size_t i = std::size_t(y) * kSize + x;
            in_frame += glm::dvec3(test::aov_beauty(frame, i, 0), test::aov_beauty(frame, i, 1), test::aov_beauty(frame, i, 2));
            in_samples += glm::dvec3(test::aov_beauty(sampled, i, 0), test::aov_beauty(sampled, i, 1), test::aov_beauty(sampled, i, 2));
        }
    in_frame /= n;
    in_samples /= n;
    const std::string figures = fmt::format("the ball's centre, albedo 0.8: a frame ({:.4f}, {:.4f}), 64 samples ({:.4f}, {:.4f}) "
                                            "in red and green; all green is (0, 0.8)",
                                            in_frame.x, in_frame.y, in_samples.x, in_samples.y);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_NEAR(in_frame.x, 0.0, 0.01) << figures;
    EXPECT_NEAR(in_frame.y, 0.8, 0.01) << figures;
    EXPECT_NEAR(in_samples.x, 0.0, 0.02) << figures;
    EXPECT_NEAR(in_samples.y, 0.8, 0.02) << figures;
}

TEST_F(Environment, samples_are_averaged_before_the_tone_map) {
    // A ball of albedo 0.8 in a uniform white sky is 0.8 wherever it is seen (the furnace), but
    // each sample's estimate of it varies. Averaged before the tone map (FrameSettings::hdr), 64
    // samples show the tone map of 0.8; averaged after it, the mean of the tone-mapped samples,
    // which is another colour.
    Pack pack = lit_by_sky(R"({"id": "ball", "type": "prim.sphere", "inputs": {"radius": 1.0}})", "ball.distance",
                           R"({"position": [0, 0, 3], "target": [0, 0, 0], "fov_deg": 50})", R"({"color": [1.0, 1.0, 1.0]})");
    auto ball_level = [&](bool hdr) {
        FrameSettings fs = test::aov_frame(kSize);
        fs.hdr = hdr;
        HeadlessRenderer r(test::shared_context(), pack, fs, test::eye_at_camera(kSize));
        const RenderedFrame f = render_samples(r, r.scene_camera(), 0.0, 0, 64);
        double sum = 0.0;
        std::size_t n = 0;
        for (std::size_t i = 0; i < std::size_t(kSize) * kSize; ++i)
            if (test::aov_hit(f, i)) sum += f.left.pixels[4 * i + 1], ++n;
        return sum / std::max<std::size_t>(n, 1);
    };
    const double c = 0.8, expected = 255.0 * (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14);
    const double before = ball_level(true), after = ball_level(false);
    const std::string figures = fmt::format("the ball's mean 8-bit level: {:.2f} averaged before the tone map, {:.2f} after "
                                            "it; the tone map of the albedo is {:.2f}",
                                            before, after, expected);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_NEAR(before, expected, 1.0) << figures;
    EXPECT_GT(std::abs(after - expected), 3.0) << "averaging after the tone map was no different: " << figures;
}
