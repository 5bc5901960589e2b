// The environment in a GGX specular lobe (light.specular's specular_color and roughness) against the
// lobe's integral over the sky, taken here by quadrature over the hemisphere: a black metal ball in
// a uniform sky reflects what the lobe gathers of it at every angle, in a frame (the split sum) and
// as the mean of samples; a polished ball shows the image in the mirror direction; a rough floor
// under a bright cap of sky reflects it as the integral says while samples accumulate.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
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

glm::dvec3 beauty3(const RenderedFrame& f, std::size_t i) {
    return {test::aov_beauty(f, i, 0), test::aov_beauty(f, i, 1), test::aov_beauty(f, i, 2)};
}

// A black body of GGX roughness `roughness` and head-on reflectance `f0`, lit by the sky alone.
Pack metal_under_sky(const std::string& nodes, const std::string& distance, double roughness, const std::string& f0,
                     const std::string& camera, const std::string& environment) {
    return test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "metal under the sky",
      "nodes": [{0}, {{"id": "lobe", "type": "light.specular", "inputs": {{"roughness": {4}, "reflectance": {5}}}}}],
      "outputs": {{"distance": "{1}", "albedo": [0, 0, 0], "specular": "lobe.specular",
                  "specular_color": "lobe.specular_color", "roughness": "lobe.roughness"}},
      "scene": {{"camera": {2}, "light": {{"color": [0, 0, 0], "ambient": [0, 0, 0]}},
                "environment": {3}, "bounds": {{"radius": 50}}, "max_distance": 100}}
    }})", nodes, distance, camera, environment, roughness, f0));
}

// The lobe's reflectance of the sky `radiance` seen from v at a point of normal n, split by
// Schlick's Fresnel into the part F0 scales and the rest: the integral over the hemisphere of
// D Vis (n . l) L(l), by the midpoint rule in the normal's own angles.
struct Split {
    double a = 0.0, b = 0.0;
};
Split lobe_integral(glm::dvec3 n, glm::dvec3 v, double roughness, const std::function<double(glm::dvec3)>& radiance) {
    const double alpha = roughness * roughness, a2 = alpha * alpha, nv = glm::dot(n, v);
    const glm::dvec3 t = glm::normalize(std::abs(n.y) < 0.9 ? glm::cross(n, glm::dvec3(0, 1, 0)) : glm::cross(n, glm::dvec3(1, 0, 0)));
    const glm::dvec3 b = glm::cross(n, t);
    constexpr int kTheta = 256, kPhi = 512;
    constexpr double reach = kPi / 2.0;
    Split s;
    for (int i = 0; i < kTheta; ++i) {
        const double theta = (i + 0.5) * reach / kTheta, nl = std::cos(theta);
        const double d_omega = std::sin(theta) * (reach / kTheta) * (2.0 * kPi / kPhi);
        for (int j = 0; j < kPhi; ++j) {
            const double phi = (j + 0.5) * 2.0 * kPi / kPhi;
            const glm::dvec3 l = n * nl + (t * std::cos(phi) + b * std::sin(phi)) * std::sin(theta);
            const double sky = radiance(l);
            if (sky == 0.0) continue;
            const glm::dvec3 h = glm::normalize(v + l);
            const double nh = glm::dot(n, h), vh = glm::dot(v, h);
            const double q = nh * nh * (a2 - 1.0) + 1.0, distribution = a2 / (kPi * q * q);
            const double visibility = 0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nl * nl * (1.0 - a2) + a2));
            const double f = distribution * visibility * nl * sky * d_omega, edge = std::pow(1.0 - vh, 5.0);
            s.a += f * (1.0 - edge);
            s.b += f * edge;
        }
    }
    return s;
}

class EnvironmentGloss : public RuntimeTest {};

}  // namespace

TEST_F(EnvironmentGloss, a_metal_ball_in_a_uniform_sky_reflects_what_its_lobe_gathers) {
    // Each channel its own reflectance head-on: a metal's (1, 0.5) and a dielectric's (0.04).
    const glm::dvec3 f0(1.0, 0.5, 0.04), eye(0, 0, 3);
    const double roughness = 0.5;
    Pack pack = metal_under_sky(R"({"id": "ball", "type": "prim.sphere", "inputs": {"radius": 1.0}})", "ball.distance",
                                roughness, "[1.0, 0.5, 0.04]", R"({"position": [0, 0, 3], "target": [0, 0, 0], "fov_deg": 50})",
                                R"({"color": [1.0, 1.0, 1.0]})");
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
    const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 64);
    // The integral depends on the angle to the view alone: tabulated over cos, read linearly.
    constexpr int kCosines = 65;
    std::vector<Split> table(kCosines);
    for (int k = 0; k < kCosines; ++k) {
        const double nv = std::max(k / double(kCosines - 1), 1e-3);
        table[k] = lobe_integral({0, 0, 1}, {std::sqrt(1.0 - nv * nv), 0, nv}, roughness, [](glm::dvec3) { return 1.0; });
    }
    auto expected = [&](double nv) {
        const double at = std::clamp(nv, 0.0, 1.0) * (kCosines - 1);
        const int k = std::min(int(at), kCosines - 2);
        const double f = at - k, a = std::lerp(table[k].a, table[k + 1].a, f), b = std::lerp(table[k].b, table[k + 1].b, f);
        return f0 * a + b;
    };
    double frame_worst = 0.0;
    glm::dvec3 frame_sum(0.0), sampled_sum(0.0), exact_sum(0.0);
    std::size_t ball = 0;
    for (std::size_t i = 0; i < std::size_t(kSize) * kSize; ++i) {
        if (!test::aov_hit(frame, i)) continue;
        const glm::dvec3 p(test::aov_position(frame, i));
        const double nv = glm::dot(glm::normalize(p), glm::normalize(eye - p));
        const glm::dvec3 want = expected(nv);
        // Away from the rim, where a pixel spans a wide range of angles and its samples see the sky.
        if (nv < 0.2) continue;
        ++ball;
        for (int c = 0; c < 3; ++c)
            frame_worst = std::max(frame_worst, std::abs(test::aov_beauty(frame, i, c) / want[c] - 1.0));
        frame_sum += beauty3(frame, i);
        sampled_sum += beauty3(sampled, i);
        exact_sum += want;
    }
    const glm::dvec3 frame_error = frame_sum / exact_sum - 1.0, sampled_error = sampled_sum / exact_sum - 1.0;
    const std::string figures = fmt::format(
        "{} pixels of the ball where n.v > 0.2, roughness {}: a frame at most {:.2f} % from the integral, summed "
        "({:+.2f}, {:+.2f}, {:+.2f}) %; 64 samples summed ({:+.2f}, {:+.2f}, {:+.2f}) % in red, green, blue",
        ball, roughness, 100.0 * frame_worst, 100.0 * frame_error.x, 100.0 * frame_error.y, 100.0 * frame_error.z,
        100.0 * sampled_error.x, 100.0 * sampled_error.y, 100.0 * sampled_error.z);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    ASSERT_GT(ball, 2000u) << figures;
    EXPECT_LT(frame_worst, 0.02) << figures;
    for (int c = 0; c < 3; ++c) {
        EXPECT_LT(std::abs(frame_error[c]), 0.01) << figures;
        EXPECT_LT(std::abs(sampled_error[c]), 0.01) << figures;
    }
}

TEST_F(EnvironmentGloss, a_polished_ball_shows_the_image_in_the_mirror_direction) {
    // Red is the image's u, green its v; a reflectance of 1 reflects all of it at every angle.
    const std::string sky = test::write_lat_long_exr("gloss_uv", 512, 256, [](double u, double v) { return glm::dvec3(u, v, 0.0); });
    const glm::dvec3 eye(0, 0, 3);
    Pack pack = metal_under_sky(R"({"id": "ball", "type": "prim.sphere", "inputs": {"radius": 1.0}})", "ball.distance", 0.02,
                                "[1.0, 1.0, 1.0]", R"({"position": [0, 0, 3], "target": [0, 0, 0], "fov_deg": 50})",
                                fmt::format(R"({{"image": "{}"}})", sky));
    std::filesystem::remove(sky);
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
    const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 16);
    double frame_worst = 0.0, sampled_worst = 0.0;
    int checked = 0;
    for (std::size_t i = 0; i < std::size_t(kSize) * kSize; ++i) {
        if (!test::aov_hit(frame, i)) continue;
        const glm::dvec3 p(test::aov_position(frame, i)), n = glm::normalize(p), v = glm::normalize(eye - p);
        if (glm::dot(n, v) < 0.5) continue;
        const glm::dvec3 d = glm::reflect(-v, n);
        const double u = 0.5 + std::atan2(d.x, -d.z) / (2.0 * kPi), w = std::acos(d.y) / kPi;
        // Off the image's seam and its poles, where neighbouring texels are far apart in (u, v).
        if (u < 0.05 || u > 0.95 || w < 0.1 || w > 0.9) continue;
        ++checked;
        for (const auto* f : {&frame, &sampled}) {
            const double error =
                std::max(std::abs(test::aov_beauty(*f, i, 0) - u), std::abs(test::aov_beauty(*f, i, 1) - w));
            (f == &frame ? frame_worst : sampled_worst) = std::max(f == &frame ? frame_worst : sampled_worst, error);
        }
    }
    const std::string figures = fmt::format("{} pixels of the ball, roughness 0.02: the reflected (u, v) at most {:.4f} from "
                                            "the mirror direction's in a frame, {:.4f} in 16 samples",
                                            checked, frame_worst, sampled_worst);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    ASSERT_GT(checked, 1000) << figures;
    EXPECT_LT(frame_worst, 0.01) << figures;
    EXPECT_LT(sampled_worst, 0.01) << figures;
}

TEST_F(EnvironmentGloss, a_rough_floor_reflects_a_bright_cap_of_sky_as_the_integral_says) {
    // Radiance 2 within 60 degrees of the zenith, black below; the floor seen from 45 degrees up.
    // Sampled, the mean over 5 x 5 pixels must meet the lobe's integral over the cap; the split
    // sum's figure in a frame is reported beside it.
    const double radiance = 2.0, cap = kPi / 3.0, roughness = 0.5;
    const glm::dvec3 eye(0, 2, 2);
    const std::string sky = test::write_lat_long_exr("gloss_cap", 240, 120,
                                                     [&](double, double v) { return glm::dvec3(v * kPi < cap ? radiance : 0.0); });
    Pack pack = metal_under_sky(R"({"id": "ground", "type": "prim.plane"})", "ground.distance", roughness, "[1.0, 1.0, 1.0]",
                                R"({"position": [0, 2, 2], "target": [0, 0, 0], "fov_deg": 20})",
                                fmt::format(R"({{"image": "{}"}})", sky));
    std::filesystem::remove(sky);
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
    const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 64);
    auto in_cap = [&](glm::dvec3 l) { return std::acos(std::clamp(l.y, -1.0, 1.0)) < cap ? radiance : 0.0; };
    double sampled_sum = 0.0, frame_sum = 0.0, exact_sum = 0.0, sampled_worst = 0.0;
    int regions = 0;
    for (std::uint32_t cy = 8; cy < kSize; cy += 16)
        for (std::uint32_t cx = 8; cx < kSize; cx += 16) {
            const std::size_t centre = std::size_t(cy) * kSize + cx;
            const glm::dvec3 p(test::aov_position(frame, centre));
            const Split s = lobe_integral({0, 1, 0}, glm::normalize(eye - p), roughness, in_cap);
            const double exact = s.a + s.b;
            double region_sampled = 0.0, region_frame = 0.0;
            for (std::uint32_t y = cy - 2; y <= cy + 2; ++y)
                for (std::uint32_t x = cx - 2; x <= cx + 2; ++x) {
                    region_sampled += test::aov_beauty(sampled, std::size_t(y) * kSize + x, 0) / 25.0;
                    region_frame += test::aov_beauty(frame, std::size_t(y) * kSize + x, 0) / 25.0;
                }
            sampled_worst = std::max(sampled_worst, std::abs(region_sampled / exact - 1.0));
            sampled_sum += region_sampled;
            frame_sum += region_frame;
            exact_sum += exact;
            ++regions;
        }
    const std::string figures = fmt::format(
        "{} regions of the floor, roughness {}: 64 samples at most {:.2f} % from the integral a region, {:+.2f} % summed; "
        "a frame (the split sum) {:+.2f} % summed",
        regions, roughness, 100.0 * sampled_worst, 100.0 * (sampled_sum / exact_sum - 1.0), 100.0 * (frame_sum / exact_sum - 1.0));
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_LT(std::abs(sampled_sum / exact_sum - 1.0), 0.01) << figures;
    EXPECT_LT(sampled_worst, 0.03) << figures;
    EXPECT_LT(std::abs(frame_sum / exact_sum - 1.0), 0.1) << figures;
}

TEST_F(EnvironmentGloss, a_ball_over_a_metal_floor_hides_its_reflection_in_a_frame_as_in_samples) {
    // A uniform sky over a floor of roughness 0.3, with and without a ball floating over it. The
    // ball's share of each floor pixel's reflection: by the cone march in a frame, by shadowed
    // directions in 64 samples (a direction that meets the ball brings nothing).
    const std::string floor = R"({"id": "ground", "type": "prim.plane"})";
    const std::string camera = R"({"position": [0, 2.5, 3], "target": [0, 0, 0], "fov_deg": 50})";
    Pack bare = metal_under_sky(floor, "ground.distance", 0.3, "[1.0, 1.0, 1.0]", camera, R"({"color": [1.0, 1.0, 1.0]})");
    Pack with_ball = metal_under_sky(floor + R"(, {"id": "up", "type": "xform.translate", "inputs": {"offset": [0, 0.9, 0]}},
                                     {"id": "ball", "type": "prim.sphere", "inputs": {"p": "up.p", "radius": 0.6}},
                                     {"id": "both", "type": "op.union", "inputs": {"a": "ground.distance", "b": "ball.distance"}})",
                                     "both.distance", 0.3, "[1.0, 1.0, 1.0]", camera, R"({"color": [1.0, 1.0, 1.0]})");
    HeadlessRenderer r0(test::shared_context(), bare, test::aov_frame(kSize), test::eye_at_camera(kSize));
    HeadlessRenderer r1(test::shared_context(), with_ball, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame0 = r0.render(r0.scene_camera(), 0.0), frame1 = r1.render(r1.scene_camera(), 0.0);
    const RenderedFrame sampled0 = render_samples(r0, r0.scene_camera(), 0.0, 0, 64);
    const RenderedFrame sampled1 = render_samples(r1, r1.scene_camera(), 0.0, 0, 64);
    double difference = 0.0, hidden_frame = 0.0, hidden_sampled = 0.0;
    int floor_pixels = 0, hidden = 0;
    for (std::size_t i = 0; i < std::size_t(kSize) * kSize; ++i) {
        const glm::dvec4 p = test::aov_position(frame1, i);
        // Floor pixels away from the ball's own outline, where samples see both.
        if (!std::isfinite(p.w) || std::abs(p.y) > 0.05 || !test::aov_hit(frame0, i)) continue;
        const double in_frame = test::aov_beauty(frame1, i, 1) / test::aov_beauty(frame0, i, 1);
        const double in_samples = test::aov_beauty(sampled1, i, 1) / test::aov_beauty(sampled0, i, 1);
        ++floor_pixels;
        difference += std::abs(in_frame - in_samples);
        if (in_samples < 0.2) ++hidden, hidden_frame += in_frame, hidden_sampled += in_samples;
    }
    difference /= std::max(floor_pixels, 1);
    const std::string figures = fmt::format(
        "{} floor pixels: the reflection's open share in a frame differs from 64 samples' by {:.3f} on average; where the "
        "samples find it mostly hidden ({} pixels), {:.3f} in a frame against {:.3f}",
        floor_pixels, difference, hidden, hidden_frame / std::max(hidden, 1), hidden_sampled / std::max(hidden, 1));
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    ASSERT_GT(hidden, 50) << figures;
    EXPECT_LT(difference, 0.1) << figures;
    EXPECT_LT(hidden_frame / hidden, 0.25) << figures;
}
