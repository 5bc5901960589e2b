// Panoramas for offline renders: equirectangular and omni-directional stereo (ODS) frames trace
// exactly the rays their formulas promise (the GPU's depths agree with the CPU twin traced through
// projection_ray), hold no NaN, wrap around their seam, and run only the passes they need.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <set>

#include "frame/accuracy_metrics.h"
#include "frame/cpu_reference_tracer.h"
#include "frame/image_output.h"
#include "offline_scene.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kWidth = 128, kHeight = 64;
// Scene units per metre: a 0.064 m IPD becomes 0.32 units, a few pixels of disparity at the ball.
constexpr double kWorldScale = 5.0;

struct Panorama {
    RenderedFrame frame;
    StereoViews views;
    std::vector<std::byte> atlas;   // conemarch levels of the first view (centre or left)
};

Panorama render_panorama(const Pack& pack, Projection projection, const HeadPose& head,
                         StereoMode mode = StereoMode::PerEye, double world_scale = kWorldScale) {
    FrameSettings fs;
    fs.width = kWidth;
    fs.height = kHeight;
    fs.projection = projection;
    fs.stereo = mode;
    fs.cone_levels = 4;
    StereoSettings ss;
    ss.ipd_m = 0.064;
    ss.world_scale = world_scale;
    HeadlessRenderer r(test::shared_context(), pack, fs, ss);
    Panorama out;
    out.frame = r.render(head, 0.0);
    out.views = r.views();
    if (mode != StereoMode::Naive) out.atlas = r.executor().download(is_mono(projection) ? "cone.centre" : "cone.left");
    return out;
}

HeadPose looking_ahead() { return look_at({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}); }

// The CPU twin through the same per-pixel rays, with the pack's own hit rule (or, strict, a tenth
// of the epsilon and many more steps: ground truth).
ReferenceDepth panorama_reference(const test::CpuScene& cpu, const Pack& pack, Projection projection, const View& view,
                                  double side, double ipd, double half_diagonal, bool strict = false) {
    ReferenceSettings rs;
    rs.step_scale = pack.manifest.find_spec("step_scale")->value;
    rs.epsilon = strict ? 0.05 : pack.manifest.find_spec("epsilon")->value;
    rs.max_steps = strict ? 4000 : static_cast<int>(pack.manifest.find_spec("max_steps")->value);
    ReferenceDepth out{view.width, view.height, {}, {}};
    out.depth.resize(static_cast<std::size_t>(view.width) * view.height);
    out.steps.resize(out.depth.size());
    for (std::uint32_t y = 0; y < view.height; ++y)
        for (std::uint32_t x = 0; x < view.width; ++x) {
            std::size_t i = static_cast<std::size_t>(y) * view.width + x;
            Ray ray = projection_ray(projection, view, side, ipd, (x + 0.5) / view.width, (y + 0.5) / view.height);
            out.depth[i] = reference_trace(*cpu.evaluator, cpu.settings, ray.origin, ray.dir, std::tan(half_diagonal), rs,
                                           &out.steps[i]);
        }
    return out;
}

// Mean absolute RGB difference between two columns of an image, per row.
double column_step(const Rgba8Image& img, std::uint32_t a, std::uint32_t b) {
    double sum = 0.0;
    for (std::uint32_t y = 0; y < img.height; ++y)
        for (int c = 0; c < 3; ++c)
            sum += std::abs(int(img.pixels[(y * img.width + a) * 4 + c]) - int(img.pixels[(y * img.width + b) * 4 + c]));
    return sum / img.height;
}

class PanoramaAgainstReference : public RuntimeTest,
                                 public ::testing::WithParamInterface<std::tuple<Projection, StereoMode>> {};
class PanoramaLevels : public RuntimeTest, public ::testing::WithParamInterface<std::tuple<Projection, bool>> {};

}  // namespace

TEST_P(PanoramaAgainstReference, depths_agree_with_the_cpu_twin_through_the_same_rays_and_hold_no_nan) {
    auto [projection, mode] = GetParam();
    Pack pack = test::compile_pack(test::room_graph());
    auto cpu = test::cpu_scene(pack);
    // Turned a little and off-centre, so no axis lines up with the image.
    HeadPose head = look_at({0.1, 0.2, 0.3}, {0.5, 0.1, -1.0});
    Panorama p = render_panorama(pack, projection, head, mode);
    int eyes = is_mono(projection) ? 1 : 2;
    for (int eye = 0; eye < eyes; ++eye) {
        double side = is_mono(projection) ? 0.0 : eye == 0 ? -1.0 : 1.0;
        const auto& depth = eye == 0 ? p.frame.depth_left : p.frame.depth_right;
        const View& view = eye == 0 ? p.views.left : p.views.right;
        auto ref = panorama_reference(*cpu, pack, projection, view, side, p.views.ipd, p.views.pixel_half_diagonal);
        DepthComparison c = compare_depths(depth, ref.depth, p.views.pixel_half_diagonal);
        std::string what = fmt::format("{} eye {}: misclassified {:.3f}% ({} only rendered, {} only reference), depth "
                                       "error median {:.3f} p95 {:.3f} cone radii",
                                       projection_name(projection), eye, 100.0 * c.misclassified, c.only_rendered,
                                       c.only_reference, c.median_error, c.p95_error);
        SCOPED_TRACE(what);
        RecordProperty(fmt::format("eye{}", eye), what);
        EXPECT_EQ(depth.size(), std::size_t{kWidth} * kHeight);
        EXPECT_EQ(c.not_finite, 0u);
        // The floor fills the lower half of a panorama.
        EXPECT_GT(c.both_hit, c.pixels / 3);
        EXPECT_LE(c.misclassified, 0.005);
        EXPECT_LE(c.p95_error, pack.manifest.find_spec("epsilon")->value);
    }
    if (!is_mono(projection)) EXPECT_NE(p.frame.left.pixels, p.frame.right.pixels) << "the eyes are apart";
}

INSTANTIATE_TEST_SUITE_P(Projections, PanoramaAgainstReference,
                         ::testing::Values(std::tuple{Projection::Equirect, StereoMode::PerEye},
                                           std::tuple{Projection::Ods, StereoMode::PerEye},
                                           std::tuple{Projection::Ods, StereoMode::Naive}),
                         [](const auto& info) {
                             return std::string(projection_name(std::get<0>(info.param))) + "_" +
                                    (std::get<1>(info.param) == StereoMode::Naive ? "naive" : "conemarch");
                         });

// A coarse cone of a panorama's level must cover its whole block of pixels, whose rays spread
// further apart in longitude than in latitude and converge at the poles, and in ODS also start
// from eyes that move with the column: every level's bound is still a lower bound of the true hit
// of every pixel in its block. Two views: the Mandelbulb from close up (detail over a third of
// the sphere), and the room with the eyes 0.64 units apart and the ball 0.15 ahead: where a
// surface is nearer than half the IPD, an ODS block's eyes sit further apart than its cone is
// wide (without fg_origin_spread a thousand rays start past the ball).
TEST_P(PanoramaLevels, every_cone_level_is_a_lower_bound_of_the_hits_in_its_block) {
    auto [projection, bulb] = GetParam();
    Pack pack = test::compile_pack(bulb ? test::read_source_file("graphs/gallery/mandelbulb.json") : test::room_graph());
    auto cpu = test::cpu_scene(pack);
    HeadPose head = bulb ? look_at({0.25, 0.55, 1.05}, {0.0, 0.2, 0.0}) : look_at({0.1, 0.1, -1.25}, {0.0, 0.0, -2.0});
    Panorama p = render_panorama(pack, projection, head, StereoMode::PerEye, bulb ? kWorldScale : 10.0);
    const View& view = is_mono(projection) ? p.views.centre : p.views.left;
    auto ref = panorama_reference(*cpu, pack, projection, view, is_mono(projection) ? 0.0 : -1.0, p.views.ipd,
                                  p.views.pixel_half_diagonal, true);
    std::uint32_t W = view.width, H = view.height;
    double cone = std::tan(p.views.pixel_half_diagonal);
    std::size_t checked = 0, violations = 0;
    for (std::uint32_t level = 0; level < 4; ++level) {
        for (std::uint32_t y = 0; y < H; ++y)
            for (std::uint32_t x = 0; x < W; ++x) {
                double t_ref = ref.depth[static_cast<std::size_t>(y) * W + x];
                if (t_ref < 0.0) continue;
                float bound = test::atlas_cone_bound(p.atlas, W, H, level, x, y);
                ++checked;
                // The reference stops within 0.05 cone radii of the surface.
                if (bound > t_ref + 0.1 * cone * t_ref) ++violations;
            }
    }
    EXPECT_GT(checked, 2000u);
    EXPECT_EQ(violations, 0u) << violations << " of " << checked << " pixel rays start past the surface";
}

INSTANTIATE_TEST_SUITE_P(Projections, PanoramaLevels,
                         ::testing::Combine(::testing::Values(Projection::Equirect, Projection::Ods), ::testing::Bool()),
                         [](const auto& info) {
                             return std::string(projection_name(std::get<0>(info.param))) +
                                    (std::get<1>(info.param) ? "_bulb_close_up" : "_room_ball_within_half_the_ipd");
                         });

// The first and last columns are neighbours on the sphere, 2 pi / width apart like any two
// adjacent columns, so the step across the seam must look like an ordinary step between
// neighbours: no larger than the 90th percentile of the image's own column-to-column steps
// (edges of objects make the largest ones). The box behind the camera straddles the seam.
TEST_F(RuntimeTest, an_ods_frame_wraps_around_its_seam) {
    Pack pack = test::compile_pack(test::room_graph());
    Panorama p = render_panorama(pack, Projection::Ods, looking_ahead());
    for (const Rgba8Image* img : {&p.frame.left, &p.frame.right}) {
        std::vector<double> steps;
        for (std::uint32_t x = 0; x + 1 < kWidth; ++x) steps.push_back(column_step(*img, x, x + 1));
        std::sort(steps.begin(), steps.end());
        double p90 = steps[steps.size() * 9 / 10];
        double seam = column_step(*img, 0, kWidth - 1);
        RecordProperty(img == &p.frame.left ? "left" : "right",
                       fmt::format("seam step {:.2f}, neighbour steps median {:.2f} p90 {:.2f} max {:.2f}", seam,
                                   steps[steps.size() / 2], p90, steps.back()));
        EXPECT_LE(seam, p90) << fmt::format("seam step {:.2f}, 90th percentile of neighbour steps {:.2f}", seam, p90);
        EXPECT_GT(steps.back(), 0.0) << "the image should not be flat";
    }
}

// Turning the head half a turn moves the seam to the middle of the image: the frame must be the
// first one rolled by half its width. Directions and eye positions come out of sin and cos of
// different angles, so a silhouette pixel may round the other way; nearly all must match exactly.
TEST_F(RuntimeTest, an_ods_frame_turned_half_a_turn_is_the_same_frame_rolled_by_half_its_width) {
    Pack pack = test::compile_pack(test::room_graph());
    HeadPose ahead = looking_ahead();
    HeadPose behind{ahead.position, glm::angleAxis(std::numbers::pi, glm::dvec3(0.0, 1.0, 0.0)) * ahead.orientation};
    Panorama a = render_panorama(pack, Projection::Ods, ahead);
    Panorama b = render_panorama(pack, Projection::Ods, behind);
    for (int eye = 0; eye < 2; ++eye) {
        const Rgba8Image& ia = eye == 0 ? a.frame.left : a.frame.right;
        const Rgba8Image& ib = eye == 0 ? b.frame.left : b.frame.right;
        std::size_t same = 0, close = 0, total = 0;
        for (std::uint32_t y = 0; y < kHeight; ++y)
            for (std::uint32_t x = 0; x < kWidth; ++x)
                for (int c = 0; c < 3; ++c) {
                    int va = ia.pixels[(y * kWidth + (x + kWidth / 2) % kWidth) * 4 + c];
                    int vb = ib.pixels[(y * kWidth + x) * 4 + c];
                    same += va == vb;
                    close += std::abs(va - vb) <= 2;
                    ++total;
                }
        RecordProperty(fmt::format("eye{}", eye), fmt::format("{} of {} channels equal, {} within 2", same, total, close));
        EXPECT_GE(close, total * 99 / 100) << fmt::format("eye {}: only {} of {} channels within 2", eye, close, total);
    }
}

TEST_F(RuntimeTest, a_panorama_runs_only_the_passes_its_rays_allow) {
    Pack pack = test::compile_pack(test::room_graph());
    auto programs = [&](Projection projection, StereoMode mode) {
        FrameSettings fs;
        fs.width = kWidth;
        fs.height = kHeight;
        fs.projection = projection;
        fs.stereo = mode;
        fs.cone_levels = 2;
        FrameGraph g = FrameGraph::build(pack.manifest, fs, kWidth, kHeight);
        std::set<std::string> seen;
        for (const auto& pass : g.passes()) seen.insert(pass.label);
        return seen;
    };
    // ODS moves the eye with every column: no centre eye to reproject from, each eye on its own.
    std::set<std::string> ods_cones{"conemarch.left.L1",  "conemarch.left.L0", "conemarch.right.L1",
                                    "conemarch.right.L0", "shade.left",        "shade.right"};
    EXPECT_EQ(programs(Projection::Ods, StereoMode::PerEye), ods_cones);
    EXPECT_EQ(programs(Projection::Ods, StereoMode::Reproject), ods_cones);
    EXPECT_EQ(programs(Projection::Ods, StereoMode::Naive),
              (std::set<std::string>{"naive.left", "naive.right", "shade.left", "shade.right"}));
    // Equirect is one eye at the head's centre; reprojection would need two.
    EXPECT_EQ(programs(Projection::Equirect, StereoMode::Reproject),
              (std::set<std::string>{"conemarch.centre.L1", "conemarch.centre.L0", "shade.centre"}));
    EXPECT_EQ(programs(Projection::Equirect, StereoMode::Naive), (std::set<std::string>{"naive.centre", "shade.centre"}));
}

// ODS fades the eyes' separation out towards the poles (FG_ODS_FADE_START): the full IPD up to 60
// degrees of latitude, none at the zenith and nadir, where the eyes' circle would make the view swirl.
TEST(OdsPoles, the_eyes_keep_the_full_ipd_up_to_sixty_degrees_and_meet_at_the_poles) {
    View view;
    view.origin = glm::dvec3(0.0);
    view.right = {1, 0, 0};
    view.up = {0, 1, 0};
    view.forward = {0, 0, -1};
    auto separation = [&](double latitude_deg) {
        double v = 0.5 - latitude_deg / 180.0;
        Ray left = projection_ray(Projection::Ods, view, -1.0, 0.064, 0.3, v);
        Ray right = projection_ray(Projection::Ods, view, 1.0, 0.064, 0.3, v);
        EXPECT_LT(glm::length(left.dir - right.dir), 1e-12) << "both eyes look the same way";
        return glm::length(left.origin - right.origin);
    };
    EXPECT_NEAR(separation(0.0), 0.064, 1e-12);
    EXPECT_NEAR(separation(59.9), 0.064, 1e-12);
    EXPECT_NEAR(separation(-59.9), 0.064, 1e-12);
    EXPECT_NEAR(separation(75.0), 0.032, 1e-7);   // half-way: the constants are floats
    EXPECT_LT(separation(89.0), 0.064 * 0.005);
    EXPECT_LT(separation(-89.0), 0.064 * 0.005);
    EXPECT_LT(separation(90.0), 1e-12);
    // Monotone in between: no ripple a viewer would see as the horizon of the fade.
    double last = 1.0;
    for (double lat = 60.0; lat <= 90.0; lat += 0.5) {
        double s = separation(lat);
        EXPECT_LE(s, last + 1e-15);
        last = s;
    }
}
