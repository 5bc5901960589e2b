// Rendered frames agree with the CPU twin: hit/miss masks, depths, the lower-bound property of
// every conemarch level, in every stereo mode. Real lavapipe, validation on.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "frame/accuracy_metrics.h"
#include "frame/cpu_reference_tracer.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 96;

const char* kPrimitives = R"({
  "format": "fractograph-graph", "version": 1, "name": "primitives",
  "nodes": [
    {"id": "ball", "type": "prim.sphere", "inputs": {"radius": 0.6}},
    {"id": "moved", "type": "xform.translate", "inputs": {"offset": [0.7, -0.2, -0.3]}},
    {"id": "box", "type": "prim.box", "inputs": {"p": "moved.p", "size": [0.4, 0.5, 0.3], "rounding": 0.05}},
    {"id": "both", "type": "op.smooth_union", "inputs": {"a": "ball", "b": "box", "k": 0.1}}
  ],
  "outputs": {"distance": "both"},
  "scene": {"camera": {"position": [0.4, 0.5, 2.4], "target": [0.2, 0, 0], "fov_deg": 60}, "bounds": {"radius": 2.0}}
})";

struct Scene {
    std::string name;
    std::string graph;
    std::optional<HeadPose> camera;
};

std::vector<Scene> scenes() {
    return {
        {"primitives", kPrimitives, std::nullopt},
        {"bulb_from_afar", test::read_source_file("graphs/gallery/mandelbulb.json"), std::nullopt},
        // The headset filled with fractal: every pixel near the surface, the hard case for speed.
        {"bulb_filling_the_view", test::read_source_file("graphs/gallery/mandelbulb.json"),
         look_at({0.25, 0.55, 1.05}, {0.0, 0.2, 0.0})},
    };
}

struct Rendered {
    RenderedFrame frame;
    StereoViews views;
    std::vector<std::byte> atlas;   // conemarch levels of the left eye (per-eye) or centre (reproject)
};

Rendered render(const Pack& pack, const Scene& scene, StereoMode mode, std::map<std::string, double> knobs = {}) {
    FrameSettings fs;
    fs.width = fs.height = kSize;
    fs.stereo = mode;
    fs.cone_levels = 4;
    fs.count_evaluations = true;
    fs.knobs = std::move(knobs);
    StereoSettings ss;
    ss.ipd_m = 0.064;
    HeadlessRenderer r(test::shared_context(), pack, fs, ss);
    Rendered out;
    out.frame = r.render(scene.camera.value_or(r.scene_camera()), 0.0);
    out.views = r.views();
    if (mode == StereoMode::PerEye) out.atlas = r.executor().download("cone.left");
    if (mode == StereoMode::Reproject) out.atlas = r.executor().download("cone.centre");
    return out;
}

// The CPU twin with the pack's own hit rule: what the GPU should compute, in double precision.
ReferenceDepth same_rule_reference(const test::CpuScene& cpu, const View& view, double half_diagonal, const Pack& pack) {
    ReferenceSettings rs;
    rs.step_scale = pack.manifest.find_spec("step_scale")->value;
    rs.epsilon = pack.manifest.find_spec("epsilon")->value;
    rs.max_steps = static_cast<int>(pack.manifest.find_spec("max_steps")->value);
    return reference_depth(*cpu.evaluator, cpu.settings, view, half_diagonal, rs);
}

// Ground truth: a tenth of the epsilon and many more steps.
ReferenceDepth strict_reference(const test::CpuScene& cpu, const View& view, double half_diagonal, const Pack& pack) {
    ReferenceSettings rs;
    rs.step_scale = pack.manifest.find_spec("step_scale")->value;
    rs.epsilon = 0.05;
    rs.max_steps = 4000;
    return reference_depth(*cpu.evaluator, cpu.settings, view, half_diagonal, rs);
}

class RenderAgainstReference : public RuntimeTest,
                               public ::testing::WithParamInterface<std::tuple<int, StereoMode>> {};

}  // namespace

TEST_P(RenderAgainstReference, hit_masks_and_depths_agree_with_the_cpu_twin) {
    auto [scene_index, mode] = GetParam();
    Scene scene = scenes()[static_cast<std::size_t>(scene_index)];
    Pack pack = test::compile_pack(scene.graph);
    auto cpu = test::cpu_scene(pack);
    Rendered r = render(pack, scene, mode);
    for (int eye = 0; eye < 2; ++eye) {
        const View& view = eye == 0 ? r.views.left : r.views.right;
        const auto& depth = eye == 0 ? r.frame.depth_left : r.frame.depth_right;
        auto ref = same_rule_reference(*cpu, view, r.views.pixel_half_diagonal, pack);
        DepthComparison c = compare_depths(depth, ref.depth, r.views.pixel_half_diagonal);
        DepthComparison truth =
            compare_depths(depth, strict_reference(*cpu, view, r.views.pixel_half_diagonal, pack).depth,
                           r.views.pixel_half_diagonal);
        std::string what = fmt::format("{} {} eye {}: against the CPU twin misclassified {:.3f}% ({} only rendered, "
                                       "{} only reference), depth error median {:.3f} p95 {:.3f} max {:.1f} cone radii; "
                                       "against ground truth misclassified {:.3f}%, overstepped {}",
                                       scene.name, stereo_mode_name(mode), eye, 100.0 * c.misclassified,
                                       c.only_rendered, c.only_reference, c.median_error, c.p95_error, c.max_error,
                                       100.0 * truth.misclassified, truth.overstepped);
        SCOPED_TRACE(what);
        RecordProperty(fmt::format("eye{}", eye), what);
        EXPECT_EQ(c.not_finite, 0u);
        EXPECT_GT(c.both_hit, c.pixels / 20) << "the scene should be in view";
        EXPECT_LE(c.misclassified, 0.005);
        // Both stop within epsilon cone radii of the surface; float against double moves the stop
        // by a step at most.
        EXPECT_LE(c.p95_error, pack.manifest.find_spec("epsilon")->value);
        // Hardly ever a hit beyond the true surface. A fractal's distance estimate is not a strict
        // bound (the uncalibrated bias of 1 lets it overshoot by a hair near buds), so a pixel in a
        // thousand may land just past the surface; the stability suite holds calibrated packs to zero.
        EXPECT_LE(truth.overstepped, c.pixels / 1000);
        auto strict = strict_reference(*cpu, view, r.views.pixel_half_diagonal, pack);
        if (truth.overstepped > c.pixels / 1000)
            for (auto i : truth.overstepped_pixels)
                ADD_FAILURE() << fmt::format("pixel ({}, {}): rendered {:.6f}, CPU twin {:.6f}, ground truth {:.6f}", i % kSize,
                                         i / kSize, depth[i], ref.depth[i], strict.depth[i]);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, RenderAgainstReference,
    ::testing::Combine(::testing::Values(0, 1, 2),
                       ::testing::Values(StereoMode::Naive, StereoMode::PerEye, StereoMode::Reproject)),
    [](const auto& info) {
        std::string mode = stereo_mode_name(std::get<1>(info.param));
        for (auto& c : mode)
            if (c == '-') c = '_';
        return scenes()[static_cast<std::size_t>(std::get<0>(info.param))].name + "_" + mode;
    });

class ConemarchLevels : public RuntimeTest, public ::testing::WithParamInterface<StereoMode> {};

TEST_P(ConemarchLevels, every_level_is_a_lower_bound_of_the_reference_hit) {
    Scene scene = scenes()[2];
    Pack pack = test::compile_pack(scene.graph);
    auto cpu = test::cpu_scene(pack);
    StereoMode mode = GetParam();
    Rendered r = render(pack, scene, mode);
    const View& view = mode == StereoMode::PerEye ? r.views.left : r.views.centre;
    auto ref = strict_reference(*cpu, view, r.views.pixel_half_diagonal, pack);
    std::uint32_t W = view.width, H = view.height;
    double cone = std::tan(r.views.pixel_half_diagonal);
    std::size_t checked = 0, violations = 0;
    for (std::uint32_t level = 0; level < 4; ++level) {
        for (std::uint32_t y = 0; y < H; ++y)
            for (std::uint32_t x = 0; x < W; ++x) {
                double t_ref = ref.depth[static_cast<std::size_t>(y) * W + x];
                if (t_ref < 0.0) continue;
                float bound = test::atlas_cone_bound(r.atlas, W, H, level, x, y);
                ++checked;
                // The reference stops within 0.05 cone radii of the surface.
                if (bound > t_ref + 0.1 * cone * t_ref) ++violations;
            }
    }
    EXPECT_GT(checked, 1000u);
    EXPECT_EQ(violations, 0u) << violations << " of " << checked << " pixel rays start past the surface";
}

INSTANTIATE_TEST_SUITE_P(Modes, ConemarchLevels, ::testing::Values(StereoMode::PerEye, StereoMode::Reproject),
                         [](const auto& info) { return std::string(info.param == StereoMode::PerEye ? "per_eye" : "reproject"); });

TEST_F(RuntimeTest, the_two_eyes_see_different_images_shifted_by_the_disparity) {
    Scene scene = scenes()[0];
    Pack pack = test::compile_pack(scene.graph);
    Rendered r = render(pack, scene, StereoMode::Reproject);
    EXPECT_NE(r.frame.left.pixels, r.frame.right.pixels);
    // Near points appear further right in the left eye than in the right eye: the left eye's
    // silhouette of the object starts at a larger column in each row.
    long shift = 0;
    for (std::uint32_t y = 0; y < kSize; ++y) {
        auto first_hit = [&](const std::vector<float>& d) {
            for (std::uint32_t x = 0; x < kSize; ++x)
                if (d[y * kSize + x] >= 0.0f) return static_cast<long>(x);
            return -1L;
        };
        long l = first_hit(r.frame.depth_left), rr = first_hit(r.frame.depth_right);
        if (l >= 0 && rr >= 0) shift += l - rr;
    }
    EXPECT_GT(shift, 0);
}

TEST_F(RuntimeTest, two_renders_of_the_same_input_are_bit_identical) {
    Scene scene = scenes()[2];
    Pack pack = test::compile_pack(scene.graph);
    for (StereoMode mode : {StereoMode::PerEye, StereoMode::Reproject}) {
        Rendered a = render(pack, scene, mode);
        Rendered b = render(pack, scene, mode);
        EXPECT_EQ(a.frame.left.pixels, b.frame.left.pixels) << stereo_mode_name(mode);
        EXPECT_EQ(a.frame.right.pixels, b.frame.right.pixels) << stereo_mode_name(mode);
        EXPECT_EQ(0, std::memcmp(a.frame.depth_left.data(), b.frame.depth_left.data(), a.frame.depth_left.size() * 4));
        EXPECT_EQ(a.frame.stats.evaluations, b.frame.stats.evaluations);
    }
}

TEST_F(RuntimeTest, cone_marching_needs_fewer_evaluations_than_the_naive_tracer_when_the_view_is_filled) {
    Scene scene = scenes()[2];
    Pack pack = test::compile_pack(scene.graph);
    double naive = render(pack, scene, StereoMode::Naive).frame.stats.evaluations_per_pixel;
    double cone = render(pack, scene, StereoMode::PerEye).frame.stats.evaluations_per_pixel;
    double reproject = render(pack, scene, StereoMode::Reproject).frame.stats.evaluations_per_pixel;
    RecordProperty("evaluations", fmt::format("naive {:.2f}, per-eye {:.2f}, reproject {:.2f}", naive, cone, reproject));
    EXPECT_GT(naive, 1.0);
    EXPECT_LT(cone, naive);
    // Reprojection's evaluations depend on the size and the view; the benchmark compares it.
    EXPECT_GT(reproject, 0.0);
}

// Each evaluation counts the iterations its fractal loop ran. The Kleinian never leaves its loop
// early, so the count is exact; the bulb's escape-time loop leaves far from the set after a few
// iterations and runs all of them near it, so the conemarch, which removes far evaluations and
// keeps the last steps to the surface, runs more iterations per evaluation than the naive tracer.
TEST_F(RuntimeTest, the_counting_frame_counts_the_iterations_of_the_fractal_loops) {
    Scene kleinian{"kleinian", test::read_source_file("graphs/gallery/kleinian.json"), std::nullopt};
    Pack klein = test::compile_pack(kleinian.graph);
    const double loop = klein.manifest.find_spec("iterations.caves")->value;
    for (StereoMode mode : {StereoMode::Naive, StereoMode::PerEye}) {
        FrameStats stats = render(klein, kleinian, mode).frame.stats;
        std::uint64_t evaluations = 0, iterations = 0;
        for (const auto& [group, n] : stats.evaluations) evaluations += n;
        for (const auto& [group, n] : stats.iterations) iterations += n;
        EXPECT_GT(evaluations, 0u) << stereo_mode_name(mode);
        EXPECT_EQ(iterations, evaluations * static_cast<std::uint64_t>(loop)) << stereo_mode_name(mode);
    }

    Scene filled = scenes()[2];
    Pack bulb = test::compile_pack(filled.graph);
    FrameStats naive = render(bulb, filled, StereoMode::Naive).frame.stats;
    FrameStats cone = render(bulb, filled, StereoMode::PerEye).frame.stats;
    const double naive_ratio = naive.iterations_per_pixel / naive.evaluations_per_pixel;
    const double level0_ratio = static_cast<double>(cone.iterations.at("march.L0")) / cone.evaluations.at("march.L0");
    RecordProperty("iterations", fmt::format("per evaluation: naive {:.2f}, per-eye level 0 {:.2f}", naive_ratio, level0_ratio));
    EXPECT_GT(naive_ratio, 1.0);
    EXPECT_LE(naive_ratio, bulb.manifest.find_spec("iterations.bulb")->value);
    EXPECT_GT(level0_ratio, naive_ratio);
}

// A step fraction shortens every step and leaves the hit test to the whole estimate: more
// evaluations, the same surface as the CPU twin with the same rule, where a step factor of the
// same size would fatten it.
TEST_F(RuntimeTest, a_step_fraction_shortens_the_steps_and_leaves_the_surface_where_it_was) {
    Scene scene = scenes()[1];
    auto graph = nlohmann::json::parse(scene.graph);
    graph["scene"]["step_fraction"] = 0.4;
    Pack full = test::compile_pack(scene.graph), shorter = test::compile_pack(graph.dump());
    EXPECT_NEAR(shorter.manifest.find_spec("step_scale")->value, 0.4 * full.manifest.find_spec("step_scale")->value, 1e-12);
    Rendered a = render(full, scene, StereoMode::PerEye), b = render(shorter, scene, StereoMode::PerEye);
    EXPECT_GT(b.frame.stats.evaluations_per_pixel, 1.3 * a.frame.stats.evaluations_per_pixel);
    auto cpu = test::cpu_scene(shorter);
    ReferenceSettings rs;
    rs.step_scale = shorter.manifest.find_spec("step_scale")->value;
    rs.step_fraction = shorter.manifest.find_spec("step_fraction")->value;
    rs.epsilon = shorter.manifest.find_spec("epsilon")->value;
    rs.max_steps = static_cast<int>(shorter.manifest.find_spec("max_steps")->value);
    const double half = b.views.pixel_half_diagonal;
    auto ref = reference_depth(*cpu->evaluator, cpu->settings, b.views.left, half, rs);
    DepthComparison same = compare_depths(b.frame.depth_left, ref.depth, half);
    EXPECT_LE(same.misclassified, 0.01);
    // Against full steps: the hits move by a fraction of the hit threshold only.
    DepthComparison moved = compare_depths(b.frame.depth_left, std::vector<double>(a.frame.depth_left.begin(), a.frame.depth_left.end()), half);
    EXPECT_LE(moved.misclassified, 0.01);
    EXPECT_LT(moved.median_error, 0.5);
}
