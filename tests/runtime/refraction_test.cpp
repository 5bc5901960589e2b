// Glass (light.refraction) against closed-form answers, on real frames (the refraction AOV, linear):
// a slab shifts the rays through it by Snell's law, and a ball passes on Fresnel's transmission in and
// out, times Beer-Lambert's absorption along its chord, in a frame; as the mean of samples, with every
// path of internal reflections counted.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "frame/aov_images.h"
#include "offline/jittered_samples.h"
#include "aov_pixels.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 96;
constexpr double kIor = 1.5;

// Channel c of pixel i of the left eye's AOV image `name`.
double channel(const RenderedFrame& f, const char* name, std::size_t i, int c) { return test::aov_half(f, name, i, c); }

// Fresnel's unpolarised reflectance into a medium eta times as dense, at incidence cosine c.
double fresnel(double c, double eta) {
    const double sin_t2 = (1.0 - c * c) / (eta * eta);
    if (sin_t2 >= 1.0) return 1.0;
    const double t = std::sqrt(1.0 - sin_t2);
    const double rs = (c - eta * t) / (c + eta * t), rp = (t - eta * c) / (t + eta * c);
    return 0.5 * (rs * rs + rp * rp);
}

// Snell's law for a unit ray d meeting a surface of unit normal n (against d) into eta times as dense.
glm::dvec3 bend(const glm::dvec3& d, const glm::dvec3& n, double eta) {
    const double c = -glm::dot(d, n), r = 1.0 / eta;
    return r * d + (r * c - std::sqrt(1.0 - r * r * (1.0 - c * c))) * n;
}

class Refraction : public RuntimeTest {};

}  // namespace

TEST_F(Refraction, a_glass_slab_shifts_the_rays_through_it_by_snells_law) {
    // A slab 0.5 thick between z = -1.75 and -2.25 before a wall at z = -4 that glows with its own
    // (x, y): the light through the slab names the point of the wall its ray met. Snell's law bends
    // the ray in and back out parallel to itself, shifted sideways.
    Pack pack = test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "glass slab",
      "nodes": [
        {{"id": "at", "type": "xform.translate", "inputs": {{"offset": [0, 0, -2]}}}},
        {{"id": "slab", "type": "prim.box", "inputs": {{"p": "at.p", "size": [40, 40, 0.25]}}}},
        {{"id": "wall", "type": "prim.plane", "inputs": {{"normal": [0, 0, 1], "offset": 4}}}},
        {{"id": "both", "type": "op.union", "inputs": {{"a": "slab.distance", "b": "wall.distance"}}}},
        {{"id": "where", "type": "input.position"}},
        {{"id": "xyz", "type": "math.split", "inputs": {{"v": "where.value"}}}},
        {{"id": "on_slab", "type": "math.step", "inputs": {{"edge": -3.0, "x": "xyz.z"}}}},
        {{"id": "on_wall", "type": "math.step", "inputs": {{"edge": "xyz.z", "x": -3.0}}}},
        {{"id": "glass", "type": "light.refraction", "inputs": {{"ior": {0}}}}},
        {{"id": "through", "type": "math.scale", "inputs": {{"v": "glass.transmission", "s": "on_slab.value"}}}},
        {{"id": "code", "type": "math.vec3", "inputs": {{"x": "xyz.x", "y": "xyz.y", "z": 1.0}}}},
        {{"id": "glow", "type": "math.scale", "inputs": {{"v": "code.value", "s": "on_wall.value"}}}}
      ],
      "outputs": {{"distance": "both.distance", "transmission": "through.value", "ior": "glass.ior",
                  "absorption": "glass.absorption", "emission": "glow.value"}},
      "scene": {{"camera": {{"position": [0, 0, 0], "target": [0.6, 0.4, -1], "fov_deg": 50}},
                "light": {{"color": [0, 0, 0], "ambient": [0, 0, 0]}}, "albedo": [0, 0, 0],
                "bounds": {{"radius": 50}}, "max_distance": 100}}
    }})", kIor));
    // Rays stop short of a surface by up to epsilon times the pixel's cone: at the wall, 10 units
    // away and met at up to 50 degrees, the default's would move the point seen by a tenth of a unit.
    FrameSettings settings = test::aov_frame(kSize);
    settings.knobs["epsilon"] = 0.02;
    HeadlessRenderer r(test::shared_context(), pack, settings, test::eye_at_camera(kSize));
    const RenderedFrame f = r.render(r.scene_camera(), 0.0);
    const View& view = r.views().left;
    double worst = 0.0, worst_share = 0.0, smallest_shift = 1e9, largest_shift = 0.0;
    std::size_t checked = 0;
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x) {
            const std::size_t i = std::size_t(y) * kSize + x;
            const glm::dvec3 d = glm::normalize(view.ray((x + 0.5) / kSize, (y + 0.5) / kSize));
            const glm::dvec3 in = d * (1.75 / -d.z);
            const glm::dvec3 inside = bend(d, {0, 0, 1}, kIor);
            const glm::dvec3 out = in + inside * (0.5 / -inside.z);
            const glm::dvec3 wall = out + d * (1.75 / -d.z);
            const glm::dvec3 straight = d * (4.0 / -d.z);
            const double w = channel(f, "refraction", i, 2);
            ASSERT_GT(w, 0.5) << "pixel " << x << ", " << y << " passes on Fresnel's transmission twice (0.92 head-on)";
            const glm::dvec2 seen(channel(f, "refraction", i, 0) / w, channel(f, "refraction", i, 1) / w);
            const double shift = glm::length(glm::dvec2(straight - wall)), error = glm::length(seen - glm::dvec2(wall));
            worst = std::max(worst, error), worst_share = std::max(worst_share, error / shift);
            smallest_shift = std::min(smallest_shift, shift), largest_shift = std::max(largest_shift, shift);
            ++checked;
        }
    const std::string figures = fmt::format(
        "{} pixels through the slab: the wall point seen at most {:.4f} from Snell's law's, at most {:.2f} % of the "
        "shift, where the straight line's misses it by {:.3f} to {:.3f}",
        checked, worst, 100.0 * worst_share, smallest_shift, largest_shift);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GT(smallest_shift, 0.01) << "the view crosses the slab at an angle: " << figures;
    EXPECT_LT(worst_share, 0.05) << figures;
}

TEST_F(Refraction, a_glass_ball_passes_on_fresnels_transmission_and_absorbs_along_its_chord) {
    // A ball of radius 1 before a white background: a ray at incidence cosine c enters with
    // 1 - F(c), crosses a chord of 2 cos(theta_t) and meets the far side at the same angle. A frame
    // passes on (1 - F)^2 exp(-sigma chord); the mean of samples adds the internal reflections,
    // (1 - F)^2 e / (1 - F e) with e = exp(-sigma chord).
    const glm::dvec3 colour(0.5, 0.8, 1.0);
    Pack pack = test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "glass ball",
      "nodes": [
        {{"id": "ball", "type": "prim.sphere", "inputs": {{"radius": 1.0}}}},
        {{"id": "glass", "type": "light.refraction", "inputs": {{"ior": {0}, "color": [{1}, {2}, {3}], "depth": 1.0}}}}
      ],
      "outputs": {{"distance": "ball.distance", "transmission": "glass.transmission", "ior": "glass.ior",
                  "absorption": "glass.absorption"}},
      "scene": {{"camera": {{"position": [0, 0, 3], "target": [0, 0, 0], "fov_deg": 50}},
                "light": {{"color": [0, 0, 0], "ambient": [0, 0, 0]}}, "albedo": [0, 0, 0], "background": [1, 1, 1]}}
    }})", kIor, colour.x, colour.y, colour.z));
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const RenderedFrame frame = r.render(r.scene_camera(), 0.0);
    const RenderedFrame sampled = render_samples(r, r.scene_camera(), 0.0, 0, 64);
    // The angle at each pixel's own hit and normal (the AOVs): a pixel's centre ray meets the ball
    // where its cone does, a little short of the sphere, which at grazing angles turns the normal.
    const glm::dvec3 camera(0, 0, 3);
    double frame_worst = 0.0, frame_error_sum = 0.0;
    glm::dvec3 sampled_sum(0.0), series_sum(0.0);
    std::size_t ball = 0;
    for (std::size_t i = 0; i < std::size_t(kSize) * kSize; ++i) {
        const glm::dvec4 p = test::aov_position(frame, i);
        if (!std::isfinite(p.w)) continue;   // a miss
        const glm::dvec3 n(channel(frame, "normal", i, 0), channel(frame, "normal", i, 1), channel(frame, "normal", i, 2));
        const double c = glm::dot(glm::normalize(n), glm::normalize(camera - glm::dvec3(p)));
        // Towards the rim the ray meets the far side ever nearer the critical angle (41.8 degrees
        // inside; 39.5 at c = 0.3), where the exit's transmission turns on the normal's last digits.
        if (c < 0.5) continue;
        const double f = fresnel(c, kIor), chord = 2.0 * std::sqrt(1.0 - (1.0 - c * c) / (kIor * kIor));
        for (int k = 0; k < 3; ++k) {
            const double e = std::exp(std::log(colour[k]) * chord);
            const double once = (1.0 - f) * (1.0 - f) * e;
            const double error = std::abs(channel(frame, "refraction", i, k) / once - 1.0);
            frame_worst = std::max(frame_worst, error), frame_error_sum += error;
            sampled_sum[k] += channel(sampled, "refraction", i, k);
            series_sum[k] += once / (1.0 - f * e);
        }
        ++ball;
    }
    const glm::dvec3 sampled_ratio = sampled_sum / series_sum;
    const std::string figures = fmt::format(
        "{} pixels of the ball: a frame {:.3f} % on average and at most {:.3f} % from (1 - F)^2 exp(-sigma chord); "
        "the mean of 64 samples against the series of internal reflections {:.4f} {:.4f} {:.4f}",
        ball, 100.0 * frame_error_sum / std::max<std::size_t>(3 * ball, 1), 100.0 * frame_worst, sampled_ratio.x, sampled_ratio.y, sampled_ratio.z);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    ASSERT_GT(ball, 2000u) << figures;
    EXPECT_LT(frame_error_sum / std::max<std::size_t>(3 * ball, 1), 0.003) << figures;
    EXPECT_LT(frame_worst, 0.02) << figures;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sampled_ratio[k], 1.0, 0.01) << figures;
}
