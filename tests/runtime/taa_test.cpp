// Temporal anti-aliasing (FrameSettings::taa, taa.comp), judged against 16 jittered samples per
// pixel of the same pose (the reference every frame would converge to): a head that stops converges
// above 38 dB within 16 frames; a head turning at 30 degrees a second stays closer to the reference
// than one sample per pixel; a slowly circling head keeps the reference's detail; a pillar passing in front of a wall leaves no trail two frames after
// it has gone; a changed parameter starts from the new frame alone; a scene that reads time gets
// plain frames. Upsampled from 1/1.5 and 1/2 of the output per axis: a still head refines to the
// output's 16 samples; a turning head keeps its history where the view moved it. A governor level
// change, to a render scale of 0.85 and back, keeps the picture converged so far; executors that
// share one history hand it over without a copy, and show what the copy would.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "frame/frame_governor.h"
#include "offline/jittered_samples.h"
#include "offline/linear_light.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 96;

FrameSettings settings(bool taa) {
    FrameSettings fs;
    fs.width = fs.height = kSize;
    fs.cone_levels = 4;
    fs.taa = taa;
    return fs;
}

const Pack& bulb() {
    static Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    return pack;
}

// The gallery bulb from its camera, turning `degrees_per_second` about the vertical at 90 Hz.
HeadPose turning(int frame, double degrees_per_second) {
    const double yaw = glm::radians(degrees_per_second / 90.0 * frame);
    const glm::dvec3 eye(0.0, 0.6, 2.6);
    return look_at(eye, eye + glm::dvec3(2.6 * std::sin(yaw), -0.6, -2.6 * std::cos(yaw)));
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

class Taa : public RuntimeTest {};

}  // namespace

TEST_F(Taa, a_head_that_stops_converges_to_sixteen_samples) {
    HeadlessRenderer taa(test::shared_context(), bulb(), settings(true), StereoSettings{kSize, kSize});
    HeadlessRenderer plain(test::shared_context(), bulb(), settings(false), StereoSettings{kSize, kSize});
    ASSERT_TRUE(taa.graph().taa);
    // Eight frames of a 30 degree/s turn, then still: the history starts as the moving picture.
    for (std::uint32_t i = 0; i < 8; ++i) taa.render(turning(static_cast<int>(i), 30.0), 0.0, i);
    const HeadPose head = turning(7, 30.0);
    Rgba8Image reference = render_samples(plain, head, 0.0, 0, 16).left;
    const double one = test::psnr(plain.render(head, 0.0).left, reference);
    std::vector<double> still;
    for (std::uint32_t i = 8; i < 8 + 32; ++i) still.push_back(test::psnr(taa.render(head, 0.0, i).left, reference));
    std::string figures = fmt::format("bulb stopping after a turn, {}^2, against 16 samples: still 1 frame {:.1f} dB, "
                                      "16 frames {:.1f} dB, 32 frames {:.1f} dB; 1 spp {:.1f} dB",
                                      kSize, still[0], still[15], still[31], one);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GE(still[15], 38.0) << figures;
    EXPECT_GE(still[31], still[15]) << figures;
    EXPECT_GE(still[0], one) << "no frame worse than one sample: " << figures;
}

// The picture's mean in linear light.
double linear_mean(const Rgba8Image& image) {
    const auto& table = srgb8_linear_table();
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); i += 4)
        sum += table[image.pixels[i]] + table[image.pixels[i + 1]] + table[image.pixels[i + 2]];
    return sum / (3.0 * static_cast<double>(image.pixels.size() / 4));
}

TEST_F(Taa, a_still_head_keeps_its_brightness_for_three_hundred_frames) {
    constexpr std::uint32_t kStill = 64;
    FrameSettings with = settings(true), without = settings(false);
    with.width = with.height = without.width = without.height = kStill;
    HeadlessRenderer taa(test::shared_context(), bulb(), with, StereoSettings{kStill, kStill});
    HeadlessRenderer plain(test::shared_context(), bulb(), without, StereoSettings{kStill, kStill});
    const HeadPose head = turning(0, 0.0);
    const double reference = linear_mean(render_samples(plain, head, 0.0, 0, 16).left);
    double worst = 0.0, at_31 = 0.0, at_299 = 0.0;
    for (std::uint32_t i = 0; i < 300; ++i) {
        const double ratio = linear_mean(taa.render(head, 0.0, i).left) / reference;
        if (i >= 31) worst = std::max(worst, std::abs(ratio - 1.0));
        if (i == 31) at_31 = ratio;
        if (i == 299) at_299 = ratio;
    }
    const std::string figures = fmt::format("still bulb at {}^2, linear mean against 16 samples: frame 31 {:.4f}, frame 299 "
                                            "{:.4f}, worst after frame 31 {:.2f} %",
                                            kStill, at_31, at_299, 100.0 * worst);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_LE(worst, 0.005) << figures;
}

TEST_F(Taa, a_turning_head_stays_closer_to_sixteen_samples_than_one_sample) {
    HeadlessRenderer taa(test::shared_context(), bulb(), settings(true), StereoSettings{kSize, kSize});
    HeadlessRenderer plain(test::shared_context(), bulb(), settings(false), StereoSettings{kSize, kSize});
    std::vector<double> with, without;
    for (int i = 0; i < 20; ++i) {
        const HeadPose head = turning(i, 30.0);
        Rgba8Image resolved = taa.render(head, 0.0, static_cast<std::uint32_t>(i)).left;
        if (i < 8) continue;   // the history fills
        Rgba8Image reference = render_samples(plain, head, 0.0, 0, 16).left;
        with.push_back(test::psnr(resolved, reference));
        without.push_back(test::psnr(plain.render(head, 0.0).left, reference));
    }
    std::string figures = fmt::format("bulb turning 30 deg/s at 90 Hz, {}^2, median of frames 8-19 against 16 samples: "
                                      "TAA {:.1f} dB, 1 spp {:.1f} dB",
                                      kSize, median(with), median(without));
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GE(median(with), median(without) + 1.0) << figures;
}

// How much fine structure a picture shows: the mean squared difference of neighbouring pixels'
// luma (8-bit levels). Blur lowers it; noise and aliasing raise it.
double gradient_energy(const Rgba8Image& image) {
    const auto luma = [&](std::uint32_t x, std::uint32_t y) {
        const std::uint8_t* p = &image.pixels[4 * (static_cast<std::size_t>(y) * image.width + x)];
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    };
    double sum = 0.0;
    for (std::uint32_t y = 0; y + 1 < image.height; ++y)
        for (std::uint32_t x = 0; x + 1 < image.width; ++x)
            sum += std::pow(luma(x + 1, y) - luma(x, y), 2) + std::pow(luma(x, y + 1) - luma(x, y), 2);
    return sum / static_cast<double>((image.width - 1) * (image.height - 1));
}

TEST_F(Taa, a_slowly_circling_head_keeps_the_detail_of_sixteen_samples) {
    // The gallery Julia circled at 0.1-0.4 pixels a frame, the motion at which every frame resamples
    // the history by a fraction of a texel and a soft filter's loss compounds (Catmull-Rom: detail
    // 0.69 of the reference's, 2.3 dB over one sample; Lanczos-3 unsharpened: 0.89).
    static Pack julia = test::compile_pack(test::read_source_file("graphs/gallery/julia.json"));
    HeadlessRenderer taa(test::shared_context(), julia, settings(true), StereoSettings{kSize, kSize});
    FrameSettings unsharpened = settings(true);
    unsharpened.taa_sharpen = 0.0;
    HeadlessRenderer soft(test::shared_context(), julia, unsharpened, StereoSettings{kSize, kSize});
    HeadlessRenderer plain(test::shared_context(), julia, settings(false), StereoSettings{kSize, kSize});
    const glm::dvec3 back(0.6, 1.3, 3.0);
    std::vector<double> with, without, detail, soft_psnr, soft_detail;
    for (int i = 0; i < 32; ++i) {
        const double angle = glm::radians(50.0 / 90.0 * i);
        const HeadPose head = look_at(glm::dvec3(back.x * std::cos(angle) + back.z * std::sin(angle), back.y,
                                                 back.z * std::cos(angle) - back.x * std::sin(angle)),
                                      glm::dvec3(0.0));
        Rgba8Image resolved = taa.render(head, 0.0, static_cast<std::uint32_t>(i)).left;
        Rgba8Image resolved_soft = soft.render(head, 0.0, static_cast<std::uint32_t>(i)).left;
        if (i < 16 || i % 4 != 3) continue;   // the history fills
        Rgba8Image reference = render_samples(plain, head, 0.0, 0, 16).left;
        with.push_back(test::psnr(resolved, reference));
        without.push_back(test::psnr(plain.render(head, 0.0).left, reference));
        detail.push_back(gradient_energy(resolved) / gradient_energy(reference));
        soft_psnr.push_back(test::psnr(resolved_soft, reference));
        soft_detail.push_back(gradient_energy(resolved_soft) / gradient_energy(reference));
    }
    std::string figures = fmt::format("Julia circled at 50 deg/s and 90 Hz, {}^2, median of frames 19-31 against 16 samples: "
                                      "TAA {:.2f} dB, detail {:.3f} of the reference's; unsharpened {:.2f} dB, {:.3f}; 1 spp {:.2f} dB",
                                      kSize, median(with), median(detail), median(soft_psnr), median(soft_detail), median(without));
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GE(median(with), median(without) + 3.0) << figures;
    // The sharpening gives back what the resampling washed out, for little of the error.
    EXPECT_GE(median(detail), 0.93) << figures;   // measured 0.965
    EXPECT_GE(median(detail), median(soft_detail) + 0.05) << figures;   // 0.886 unsharpened
    EXPECT_GE(median(with), median(soft_psnr) - 0.3) << figures;
}

TEST_F(Taa, a_pillar_passing_a_wall_leaves_no_trail_after_two_frames) {
    // A red pillar before a blue wall; the head moves sideways so the pillar crosses the view.
    Pack pack = test::compile_pack(R"({
      "format": "fractograph-graph", "version": 1, "name": "pillar and wall",
      "nodes": [
        {"id": "wall_at", "type": "xform.translate", "inputs": {"offset": [0.0, 0.0, -1.0]}},
        {"id": "wall", "type": "prim.box", "inputs": {"p": "wall_at.p", "size": [4.0, 2.0, 0.1]}},
        {"id": "pillar", "type": "prim.box", "inputs": {"size": [0.08, 2.0, 0.08]}},
        {"id": "both", "type": "op.union", "inputs": {"a": "wall.distance", "b": "pillar.distance"}},
        {"id": "at", "type": "input.position"},
        {"id": "xyz", "type": "math.split", "inputs": {"v": "at.value"}},
        {"id": "front", "type": "math.step", "inputs": {"edge": -0.5, "x": "xyz.z"}},
        {"id": "colour", "type": "math.mix", "inputs": {"a": [0.1, 0.2, 0.9], "b": [0.9, 0.1, 0.1], "t": "front.value"}}
      ],
      "outputs": {"distance": "both.distance", "albedo": "colour.value"},
      "scene": {"camera": {"position": [0, 0, 2], "target": [0, 0, 0], "fov_deg": 60}, "bounds": {"radius": 5}}
    })");
    HeadlessRenderer taa(test::shared_context(), pack, settings(true), StereoSettings{kSize, kSize});
    HeadlessRenderer plain(test::shared_context(), pack, settings(false), StereoSettings{kSize, kSize});
    auto head = [](int i) {
        glm::dvec3 eye(-0.6 + 0.04 * i, 0.0, 2.0);
        return look_at(eye, eye + glm::dvec3(0.0, 0.0, -1.0));
    };
    auto red = [](const Rgba8Image& im, std::size_t i) { return im.pixels[4 * i] > im.pixels[4 * i + 2]; };
    std::vector<Rgba8Image> truth;
    std::size_t checked = 0, trails = 0;
    for (int i = 0; i < 30; ++i) {
        Rgba8Image resolved = taa.render(head(i), 0.0, static_cast<std::uint32_t>(i)).left;
        truth.push_back(plain.render(head(i), 0.0).left);

        if (i < 2) continue;
        // Pixels that showed the pillar two frames ago, the wall now and in the frame between, and
        // away from the pillar's edge now: their colour must be the wall's.
        const Rgba8Image &now = truth[static_cast<std::size_t>(i)], &before = truth[static_cast<std::size_t>(i - 2)],
                         &between = truth[static_cast<std::size_t>(i - 1)];
        for (std::uint32_t y = 1; y + 1 < kSize; ++y)
            for (std::uint32_t x = 1; x + 1 < kSize; ++x) {
                std::size_t p = static_cast<std::size_t>(y) * kSize + x;
                if (!red(before, p) || red(between, p) || red(now, p) || red(now, p - 1) || red(now, p + 1)) continue;
                ++checked;
                // The pillar's red bleeding into the wall's blue by more than a few levels.
                trails += resolved.pixels[4 * p] > now.pixels[4 * p] + 24;
            }
    }
    std::string figures = fmt::format("{} pixels the pillar left two frames before, {} of them still tinted by it", checked, trails);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GT(checked, 100u) << figures;
    EXPECT_EQ(trails, 0u) << figures;
}

TEST_F(Taa, a_changed_parameter_starts_from_the_new_frame_alone) {
    HeadlessRenderer taa(test::shared_context(), bulb(), settings(true), StereoSettings{kSize, kSize});
    const HeadPose head = turning(0, 0.0);
    for (std::uint32_t i = 0; i < 4; ++i) taa.render(head, 0.0, i);
    ASSERT_TRUE(taa.executor().set_param("power", Constant::scalar(ValueType::Float, 6.0)));
    RenderedFrame f = taa.render(head, 0.0, 4);
    // No history: the resolved frame is this frame's jittered samples, byte for byte.
    EXPECT_EQ(f.left.pixels, rgba8_from_bytes(taa.executor().download("jittered.left"), kSize, kSize).pixels);
    RenderedFrame g = taa.render(head, 0.0, 5);
    EXPECT_NE(g.left.pixels, rgba8_from_bytes(taa.executor().download("jittered.left"), kSize, kSize).pixels)
        << "the next frame blends its history again";
}

TEST_F(Taa, a_scene_that_reads_time_gets_plain_frames) {
    Pack pack = test::compile_pack(R"({
      "format": "fractograph-graph", "version": 1, "name": "pulsing ball",
      "nodes": [
        {"id": "now", "type": "input.time"},
        {"id": "wobble", "type": "math.sin", "inputs": {"x": "now.value"}},
        {"id": "radius", "type": "math.add", "inputs": {"a": 0.8, "b": "wobble.value"}},
        {"id": "ball", "type": "prim.sphere", "inputs": {"radius": "radius.value"}}
      ],
      "outputs": {"distance": "ball.distance"},
      "scene": {"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "fov_deg": 60}}
    })");
    HeadlessRenderer taa(test::shared_context(), pack, settings(true), StereoSettings{kSize, kSize});
    EXPECT_FALSE(taa.graph().taa);
    EXPECT_EQ(taa.graph().find_image("taa.left"), nullptr);
}

namespace {

// Temporal upsampling by `factor` to kSize, the eyes traced plainly (the test judges the resolve,
// not how a coarser march differs).
FrameSettings upsampled(double factor, std::uint32_t size = kSize) {
    FrameSettings fs = settings(true);
    fs.width = fs.height = size;
    fs.stereo = StereoMode::Naive;
    set_taa_upscale(fs, factor);
    return fs;
}

FrameSettings naive(bool taa) {
    FrameSettings fs = settings(taa);
    fs.stereo = StereoMode::Naive;
    return fs;
}

}  // namespace

TEST_F(Taa, upsampling_marches_pixels_of_exactly_the_factor_and_shows_the_output_size) {
    // 95 is no multiple of 1.5: 64 marched pixels of 1.5 output pixels reach past its edge.
    FrameSettings fs = upsampled(1.5, 95);
    EXPECT_EQ(fs.width, 64u);
    EXPECT_DOUBLE_EQ(fs.detail_scale, 1.0 / 1.5);
    StereoSettings stereo;
    set_marched_size(stereo, fs);
    HeadlessRenderer r(test::shared_context(), bulb(), fs, stereo);
    EXPECT_EQ(r.graph().width, 64u);
    EXPECT_EQ(r.graph().output_width, 95u);
    EXPECT_EQ(r.graph().find_image("final.left")->width, 95u);
    EXPECT_EQ(r.graph().find_image("taa.left")->width, 95u);
    EXPECT_EQ(r.graph().find_image("jittered.left")->width, 64u);
    const Fov shown = r.scene_fov();
    const View& left = r.views().left;
    EXPECT_NEAR((left.fov.right - left.fov.left) / 64.0, 1.5 * (shown.right - shown.left) / 95.0, 1e-12);
    EXPECT_NEAR(left.fov.left - r.views().jitter.x * (left.fov.right - left.fov.left) / 64.0, shown.left, 1e-12);
    RenderedFrame f = r.render(r.scene_camera(), 0.0);
    EXPECT_EQ(f.left.width, 95u);
    EXPECT_EQ(f.left.pixels.size(), 95u * 95u * 4u);
}

TEST_F(Taa, an_upsampled_head_that_stops_converges_to_sixteen_samples_of_the_output) {
    HeadlessRenderer plain(test::shared_context(), bulb(), naive(false), StereoSettings{kSize, kSize});
    const HeadPose head = turning(0, 0.0);
    Rgba8Image reference = render_samples(plain, head, 0.0, 0, 16).left;
    const double one = test::psnr(plain.render(head, 0.0).left, reference);
    std::string figures = fmt::format("bulb still, {}^2 shown, against 16 samples (1 spp {:.1f} dB):", kSize, one);
    for (double factor : {1.5, 2.0}) {
        FrameSettings fs = upsampled(factor);
        StereoSettings stereo;
        set_marched_size(stereo, fs);
        HeadlessRenderer taau(test::shared_context(), bulb(), fs, stereo);
        ASSERT_EQ(taau.executor().refined_frames(), factor == 2.0 ? 64u : 36u);
        std::vector<double> psnr;
        for (std::uint32_t i = 0; i <= taau.executor().refined_frames(); ++i)
            psnr.push_back(test::psnr(taau.render(head, 0.0, i).left, reference));
        figures += fmt::format(" upsampled by {}: first frame {:.1f} dB, refined {:.1f} dB;", factor, psnr.front(), psnr.back());
        EXPECT_GE(psnr.back(), 45.0) << figures;
    }
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
}

TEST_F(Taa, an_upsampled_turning_head_keeps_its_history_where_it_moved) {
    // Against the same marched frames filtered up without history: a history reprojected to the
    // wrong place would blur or ghost and lose to them.
    FrameSettings fs = upsampled(2.0);
    StereoSettings stereo;
    set_marched_size(stereo, fs);
    HeadlessRenderer taau(test::shared_context(), bulb(), fs, stereo);
    HeadlessRenderer fresh(test::shared_context(), bulb(), fs, stereo);
    HeadlessRenderer plain(test::shared_context(), bulb(), naive(false), StereoSettings{kSize, kSize});
    std::vector<double> with, without;
    for (int i = 0; i < 24; ++i) {
        const HeadPose head = turning(i, 30.0);
        Rgba8Image resolved = taau.render(head, 0.0, static_cast<std::uint32_t>(i)).left;
        fresh.executor().forget_history();
        Rgba8Image filtered = fresh.render(head, 0.0, static_cast<std::uint32_t>(i)).left;
        if (i < 12) continue;   // the history fills
        Rgba8Image reference = render_samples(plain, head, 0.0, 0, 16).left;
        with.push_back(test::psnr(resolved, reference));
        without.push_back(test::psnr(filtered, reference));
    }
    std::string figures = fmt::format("bulb turning 30 deg/s, upsampled by 2 to {}^2, median of frames 12-23 against 16 "
                                      "samples: with history {:.1f} dB, each frame filtered up alone {:.1f} dB",
                                      kSize, median(with), median(without));
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GE(median(with), median(without) + 1.5) << figures;
}

TEST_F(Taa, a_governor_level_change_keeps_the_converged_picture) {
    // The two levels resolve to the same 96^2: the lower marches 0.85 of it per axis (upsampling by
    // 1/0.85, the default ladder's first step in scale) and continues the history of the level
    // before, both ways. A level that started afresh would show one jittered sample per marched
    // pixel. (From 1 to 0.7 the first frame lost 1.1 dB, less than that level's own 1.3 dB.)
    FrameSettings full = settings(true);
    GovernorLevel top, lower;
    lower.render_scale = 0.85;
    const FrameSettings at_top = settings_at_level(full, top, kSize, kSize), at_lower = settings_at_level(full, lower, kSize, kSize);
    ASSERT_EQ(at_lower.shown_width(), kSize);
    ASSERT_EQ(at_lower.width, 82u);   // 96 / (1 / 0.85), whole marched pixels
    StereoSettings top_stereo, lower_stereo;
    set_marched_size(top_stereo, at_top);
    set_marched_size(lower_stereo, at_lower);
    HeadlessRenderer a(test::shared_context(), bulb(), at_top, top_stereo);
    HeadlessRenderer b(test::shared_context(), bulb(), at_lower, lower_stereo);
    HeadlessRenderer fresh(test::shared_context(), bulb(), at_lower, lower_stereo);
    HeadlessRenderer plain(test::shared_context(), bulb(), settings(false), StereoSettings{kSize, kSize});
    const auto score = [&](HeadlessRenderer& r, int i) {
        const HeadPose head = turning(i, 30.0);
        return test::psnr(r.render(head, 0.0, static_cast<std::uint32_t>(i)).left, render_samples(plain, head, 0.0, 0, 16).left);
    };
    for (int i = 0; i < 15; ++i) a.render(turning(i, 30.0), 0.0, static_cast<std::uint32_t>(i));
    const double before_down = score(a, 15);
    ASSERT_TRUE(b.executor().take_history(a.executor()));
    const double after_down = score(b, 16);
    const double afresh = score(fresh, 16);
    for (int i = 17; i < 31; ++i) b.render(turning(i, 30.0), 0.0, static_cast<std::uint32_t>(i));
    const double before_up = score(b, 31);
    ASSERT_TRUE(a.executor().take_history(b.executor()));
    const double after_up = score(a, 32);
    const std::string figures = fmt::format(
        "bulb turning 30 deg/s, {}^2 shown, against 16 samples: down to scale 0.85 {:.2f} -> {:.2f} dB (started afresh "
        "{:.2f}), back up {:.2f} -> {:.2f} dB",
        kSize, before_down, after_down, afresh, before_up, after_up);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GE(after_down, before_down - 1.0) << figures;
    EXPECT_GE(after_up, before_up - 1.0) << figures;
    EXPECT_LT(afresh, before_down - 1.0) << "the test tells a carried history from a fresh one: " << figures;

    // A still head: the lower level continues the plain mean of the samples (still_frames goes on).
    // Its picture is then the lower level's own, which differs from the full-size reference by
    // the conemarch's fringe on the coarser grid: the change costs nothing beyond that.
    const HeadPose head = turning(0, 0.0);
    const Rgba8Image reference = render_samples(plain, head, 0.0, 0, 16).left;
    const auto still_psnr = [&](HeadlessRenderer& r, std::uint32_t frames) {
        r.executor().forget_history();
        for (std::uint32_t i = 0; i + 1 < frames; ++i) r.render(head, 0.0, i);
        return test::psnr(r.render(head, 0.0, frames - 1).left, reference);
    };
    const double lower_own = still_psnr(b, 32);
    const double still_before = still_psnr(a, 32);
    ASSERT_TRUE(b.executor().take_history(a.executor()));
    const double still_after = test::psnr(b.render(head, 0.0, 32).left, reference);
    const std::string still = fmt::format("still bulb: scale 1 -> 0.85 {:.2f} -> {:.2f} dB; 32 frames at 0.85 alone {:.2f} dB",
                                          still_before, still_after, lower_own);
    std::printf("%s\n", still.c_str());
    EXPECT_GT(b.executor().frame().still_frames, 16u) << "the head stayed still across the change";
    EXPECT_GE(still_after, lower_own - 0.5) << still;
}

TEST_F(Taa, executors_sharing_one_history_hand_it_over_without_a_copy) {
    // As the headset player holds its levels: both executors' TAA history is the same two images
    // per eye, so a level change copies nothing, and shows what copying would, byte for byte.
    FrameSettings full = settings(true);
    GovernorLevel top, lower;
    lower.render_scale = 0.85;
    const FrameSettings at_top = settings_at_level(full, top, kSize, kSize), at_lower = settings_at_level(full, lower, kSize, kSize);
    StereoSettings top_stereo, lower_stereo;
    set_marched_size(top_stereo, at_top);
    set_marched_size(lower_stereo, at_lower);
    SharedTaaHistory shared;
    HeadlessRenderer a(test::shared_context(), bulb(), at_top, top_stereo, nullptr, &shared);
    HeadlessRenderer b(test::shared_context(), bulb(), at_lower, lower_stereo, nullptr, &shared);
    HeadlessRenderer copying_a(test::shared_context(), bulb(), at_top, top_stereo);
    HeadlessRenderer copying_b(test::shared_context(), bulb(), at_lower, lower_stereo);
    const auto handles = [](HeadlessRenderer& r) {
        std::vector<VkImage> out;
        for (const char* name : {"taa.left", "taa.left.previous", "taa_depth.right", "taa_depth.right.previous"})
            out.push_back(r.executor().image(name).handle());
        std::sort(out.begin(), out.end());
        return out;
    };
    EXPECT_EQ(handles(a), handles(b)) << "the two levels hold one history";
    EXPECT_NE(handles(copying_a), handles(copying_b));

    for (int i = 0; i < 15; ++i) {
        a.render(turning(i, 30.0), 0.0, static_cast<std::uint32_t>(i));
        copying_a.render(turning(i, 30.0), 0.0, static_cast<std::uint32_t>(i));
    }
    const auto same_frames = [](HeadlessRenderer& shared_level, HeadlessRenderer& copying_level, int from, int to) {
        int same = 0;
        for (int i = from; i < to; ++i) {
            const HeadPose head = turning(i, 30.0);
            same += shared_level.render(head, 0.0, static_cast<std::uint32_t>(i)).left.pixels ==
                    copying_level.render(head, 0.0, static_cast<std::uint32_t>(i)).left.pixels;
        }
        return same;
    };
    ASSERT_TRUE(b.executor().take_history(a.executor()));
    ASSERT_TRUE(copying_b.executor().take_history(copying_a.executor()));
    EXPECT_EQ(same_frames(b, copying_b, 15, 19), 4) << "down a level: the shared history is the copied one";
    ASSERT_TRUE(a.executor().take_history(b.executor()));
    ASSERT_TRUE(copying_a.executor().take_history(copying_b.executor()));
    EXPECT_EQ(same_frames(a, copying_a, 19, 22), 3) << "and back up";
}
