// The camera's effects over jittered samples against closed forms. Depth of field (a thin lens,
// offline/depth_of_field.h): an edge at the focus distance stays sharp (inside one pixel), and one
// at twice the focus distance blurs by the circle of confusion, aperture * (1/focus - 1/distance)
// across, within 10 %. Motion blur (a camera path's shutter): an edge blurs by the camera's motion
// while the shutter is open, within 10 %. Adaptive sampling: pixels whose mean has converged stop
// (their tiles leave the passes), the rest take every sample, and the picture stays the uniform one.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "offline/depth_of_field.h"
#include "offline/display_transform.h"
#include "offline/linear_light.h"
#include "offline/jittered_samples.h"
#include "offline/path_render.h"
#include "offline/sample_accumulator.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 128;
constexpr double kFovDeg = 40.0, kFocus = 2.0, kAperture = 0.2;

// A glowing wall whose front face is `distance` ahead and whose left edge is on the view's axis
// (emission only: a lit edge would darken where the normal's taps reach round the corner).
Pack wall_at(double distance) {
    return test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "edge",
      "nodes": [
        {{"id": "at", "type": "xform.translate", "inputs": {{"offset": [10.0, 0.0, {0}]}}}},
        {{"id": "wall", "type": "prim.box", "inputs": {{"p": "at.p", "size": [10.0, 10.0, 0.05]}}}},
        {{"id": "glow", "type": "light.emission", "inputs": {{"color": [0.7, 0.7, 0.7], "intensity": 1.0, "mask": 1.0}}}}
      ],
      "outputs": {{"distance": "wall.distance", "emission": "glow.emission"}},
      "scene": {{"camera": {{"position": [0, 0, 0], "target": [0, 0, -1], "fov_deg": {1}}},
                "light": {{"direction": [0, 0, 1], "color": [0, 0, 0], "ambient": [0, 0, 0]}},
                "background": [0, 0, 0], "bounds": {{"radius": 60}}}}
    }})", -distance - 0.05, kFovDeg));
}

// The scene-linear light a display level shows: the tone map inverted (samples are averaged before
// it, so a blur is a blur of light).
double scene_light(std::uint8_t level) {
    double lo = 0.0, hi = 64.0;
    for (int i = 0; i < 60; ++i) (tonemap_beauty(0.5 * (lo + hi)) < level / 255.0 ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
}

// The centre row's light over the wall's.
std::vector<double> centre_row(const Rgba8Image& image) {
    const std::size_t row = kSize / 2;
    std::vector<double> light(kSize);
    for (std::size_t x = 0; x < kSize; ++x) light[x] = scene_light(image.pixels[4 * (row * kSize + x)]);
    const double wall = light[kSize - 4];
    for (double& v : light) v /= wall;
    return light;
}

// Pixels of the centre row partly covered by the wall (between 5 and 95 % of its light): 1 for a
// sharp edge, which falls inside one pixel.
std::size_t edge_pixels(const Rgba8Image& image) {
    std::size_t n = 0;
    for (double v : centre_row(image)) n += v > 0.05 && v < 0.95;
    return n;
}

// The 10-90 % width in pixels of the edge along the centre row, between pixel centres.
double edge_width(const Rgba8Image& image) {
    const std::vector<double> light = centre_row(image);
    const double wall = 1.0;
    auto crossing = [&](double level) {
        for (std::size_t x = 0; x + 1 < kSize; ++x)
            if (light[x] < level * wall && light[x + 1] >= level * wall)
                return x + (level * wall - light[x]) / (light[x + 1] - light[x]);
        return -1.0;
    };
    return crossing(0.9) - crossing(0.1);
}

// The 10-90 % width of an edge blurred by a uniform disc of radius 1: where the disc's area left of
// x reaches 10 % and 90 %.
double disc_edge_width() {
    auto area_left_of = [](double s) { return (std::acos(-s) + s * std::sqrt(1.0 - s * s)) / glm::pi<double>(); };
    auto solve = [&](double level) {
        double lo = -1.0, hi = 1.0;
        for (int i = 0; i < 60; ++i) (area_left_of(0.5 * (lo + hi)) < level ? lo : hi) = 0.5 * (lo + hi);
        return 0.5 * (lo + hi);
    };
    return solve(0.9) - solve(0.1);
}

RenderedFrame blurred_frame(double distance, const SampleBudget& budget, bool count_evaluations = false) {
    Pack pack = wall_at(distance);
    FrameSettings fs;
    fs.width = fs.height = kSize;
    fs.stereo = StereoMode::Naive;
    fs.count_evaluations = count_evaluations;
    fs.hdr = true;   // as fgplay render --samples
    StereoSettings stereo{kSize, kSize};
    stereo.ipd_m = 0.0;
    HeadlessRenderer r(test::shared_context(), pack, fs, stereo);
    focus_depth_of_field(r, kAperture, kFocus, r.scene_camera(), 0.0, 0);
    const HeadPose head = r.scene_camera();
    return render_samples(r, [&](double) { return SampleMoment{head, 0.0}; }, 0, budget);
}

Rgba8Image blurred(double distance) {
    SampleBudget uniform;
    uniform.samples = 64;
    return blurred_frame(distance, uniform).left;
}

class DepthOfField : public RuntimeTest {};
class MotionBlur : public RuntimeTest {};

}  // namespace

TEST_F(DepthOfField, an_edge_in_focus_stays_sharp_and_one_twice_as_far_blurs_by_the_circle_of_confusion) {
    const std::size_t sharp = edge_pixels(blurred(kFocus));
    const double far = edge_width(blurred(2.0 * kFocus));
    // The circle of confusion's radius in pixels: half of aperture * (1/F - 1/d) radians.
    const double pixel_tan = 2.0 * std::tan(glm::radians(kFovDeg / 2.0)) / kSize;
    const double radius = 0.5 * kAperture * (1.0 / kFocus - 1.0 / (2.0 * kFocus)) / pixel_tan;
    const double expected = disc_edge_width() * radius;
    std::string figures = fmt::format("edge in focus across {} pixel(s); 10-90 % at twice the focus {:.2f} px, the thin lens {:.2f} px "
                                      "(circle of confusion {:.2f} px across)",
                                      sharp, far, expected, 2.0 * radius);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_LE(sharp, 1u) << figures;
    EXPECT_NEAR(far, expected, 0.1 * expected) << figures;
}

TEST_F(DepthOfField, the_focus_defaults_to_what_the_view_centre_sees) {
    Pack pack = wall_at(3.0);
    FrameSettings fs;
    fs.width = fs.height = 32;
    StereoSettings stereo{32, 32};
    stereo.ipd_m = 0.0;
    HeadlessRenderer r(test::shared_context(), pack, fs, stereo);
    // The centre pixel lies just right of the edge, on the wall 3 ahead.
    EXPECT_NEAR(focus_depth_of_field(r, 0.1, 0.0, r.scene_camera(), 0.0, 0), 3.0, 0.01);
    HeadPose away = look_at({0, 0, 0}, {-1, 0, 0});
    EXPECT_THROW(focus_depth_of_field(r, 0.1, 0.0, away, 0.0, 0), std::runtime_error);
}

TEST_F(MotionBlur, a_camera_moving_while_the_shutter_is_open_blurs_an_edge_by_its_motion) {
    // Sideways at 3 units a second, 30 frames a second, the shutter open half of each: the camera
    // moves 0.05 while it looks, which the wall 2 ahead turns into a box blur that many pixels long.
    const double speed = 3.0, fps = 30.0, shutter = 0.5, distance = 2.0;
    Pack pack = wall_at(distance);
    Diagnostics diag;
    auto path = CameraPath::parse(nlohmann::json::parse(R"({
      "format": "fractograph-camera-path", "version": 1, "fps": 30, "interpolation": "linear",
      "keyframes": [{"time": 0.0, "position": [-1.0, 0.0, 0.0], "target": [-1.0, 0.0, -1.0]},
                    {"time": 1.0, "position": [2.0, 0.0, 0.0], "target": [2.0, 0.0, -1.0]}]
    })"), 1.0, diag);
    ASSERT_TRUE(path) << diag.format();
    PathRenderSettings s;
    s.projection = Projection::Perspective;
    s.stereo = StereoMode::Naive;
    s.width = s.height = kSize;
    s.ipd_m = 0.0;
    s.samples = 64;
    s.shutter = shutter;
    PathRenderer renderer(test::shared_context(), pack, *path, s);
    // Frame 10 opens with the camera at x = 0, the edge at the view's centre.
    Rgba8Image picture = renderer.render(10);
    Rgba8Image left{kSize, kSize, std::vector<std::uint8_t>(kSize * kSize * 4)};
    for (std::uint32_t y = 0; y < kSize; ++y)
        std::copy_n(picture.pixels.begin() + 4 * (y * picture.width), 4 * kSize, left.pixels.begin() + 4 * (y * kSize));
    const double pixel_tan = 2.0 * std::tan(glm::radians(kFovDeg / 2.0)) / kSize;
    const double length = speed * shutter / fps / distance / pixel_tan;   // the blur in pixels
    const double expected = 0.8 * length;                                  // 10-90 % of a linear ramp
    const double measured = edge_width(left);
    std::string figures = fmt::format("edge 10-90 % {:.2f} px under a {:.2f} px motion blur (a ramp's {:.2f})", measured,
                                      length, expected);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_NEAR(measured, expected, 0.1 * expected) << figures;
}

TEST(AdaptiveSampling, a_pixel_noise_is_the_standard_error_of_its_mean_and_only_its_tile_samples_on) {
    // 24x16 pixels (3x2 tiles): pixel (3, 3) alternates between black and white, the rest stay grey.
    SampleAccumulator acc;
    SampledTiles all(24, 16);
    for (int k = 0; k < 4; ++k) {
        Rgba8Image sample{24, 16, std::vector<std::uint8_t>(24 * 16 * 4, 128)};
        for (int c = 0; c < 3; ++c) sample.pixels[4 * (3 * 24 + 3) + c] = k % 2 ? 255 : 0;
        acc.add(sample, &all);
    }
    // Luma 0, 1, 0, 1: the sample variance 1/3, the mean's standard error sqrt(1/3 / 4).
    EXPECT_NEAR(acc.noise(3 * 24 + 3), std::sqrt(1.0 / 12.0), 1e-9);
    EXPECT_EQ(acc.noise(0), 0.0);
    SampledTiles noisy = acc.tiles_above(0.01);
    // The noisy pixel's tile (0, 0) alone.
    EXPECT_EQ(noisy.active, (std::vector<std::uint8_t>{1, 0, 0, 0, 0, 0}));
    // The next sample goes to that tile alone: its pixels count 5, the others 4.
    acc.add(Rgba8Image{24, 16, std::vector<std::uint8_t>(24 * 16 * 4, 128)}, &noisy);
    EXPECT_EQ(acc.counts()[0], 5u);
    EXPECT_EQ(acc.counts()[8], 4u);
    EXPECT_EQ(acc.counts()[23], 4u);
    EXPECT_EQ(acc.mean().pixels[4 * 23], 128) << "a pixel's mean divides by its own count";
}

TEST_F(DepthOfField, adaptive_sampling_stops_converged_pixels_and_keeps_the_uniform_picture) {
    // The blurred edge twice the focus away: noisy across its circle of confusion, flat either side.
    SampleBudget uniform;
    uniform.samples = 64;
    SampleBudget adaptive = uniform;
    adaptive.noise = 0.01;
    adaptive.min_samples = 8;
    SampleProgress last;
    adaptive.progress = [&](const SampleProgress& p) { last = p; };
    const RenderedFrame all = blurred_frame(2.0 * kFocus, uniform, true);
    const RenderedFrame some = blurred_frame(2.0 * kFocus, adaptive, true);
    double evaluations_all = 0.0, evaluations_some = 0.0;
    for (const auto& [_, n] : all.stats.evaluations) evaluations_all += static_cast<double>(n);
    for (const auto& [_, n] : some.stats.evaluations) evaluations_some += static_cast<double>(n);
    const auto& lin = srgb8_linear_table();
    double worst = 0.0;
    for (std::size_t i = 0; i < all.left.pixels.size(); ++i)
        if (i % 4 != 3) worst = std::max(worst, std::abs(lin[all.left.pixels[i]] - lin[some.left.pixels[i]]));
    const double width_all = edge_width(all.left), width_some = edge_width(some.left);
    std::string figures = fmt::format("{:.1f} samples a pixel of 64 ({:.0f} % of the tiles still sampling at the end), {:.0f} % of "
                                      "the evaluations; edge 10-90 % {:.2f} px against {:.2f}; pixels at most {:.4f} apart in "
                                      "linear light",
                                      last.mean_samples, 100.0 * last.tiles_sampling, 100.0 * evaluations_some / evaluations_all,
                                      width_some, width_all, worst);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_LT(last.mean_samples, 0.6 * 64) << figures;
    EXPECT_LT(evaluations_some, 0.7 * evaluations_all) << figures;
    EXPECT_NEAR(width_some, width_all, 0.05 * width_all) << figures;
    EXPECT_LE(worst, 0.01) << figures;
}
