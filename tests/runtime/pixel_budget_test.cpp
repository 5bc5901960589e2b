// Fewer pixels, each honestly: the lens mask never marches what the lens hides and leaves the rest
// of the image bit for bit as it was; fixed foveation marches a quarter of the periphery, keeps the
// fovea exact and stays close to ground truth elsewhere. Real lavapipe, validation on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "frame/accuracy_metrics.h"
#include "frame/cpu_reference_tracer.h"
#include "frame/frame_graph.h"
#include "frame/lens_mask.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 96;

// The gallery bulb with the headset filled by fractal: the view where pixels cost the most.
const HeadPose kFilled = look_at({0.25, 0.55, 1.05}, {0.0, 0.2, 0.0});

const Pack& bulb() {
    static Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    return pack;
}

struct Rendered {
    RenderedFrame frame;
    StereoViews views;
};

Rendered render(StereoMode mode, bool lens, double foveation) {
    FrameSettings fs;
    fs.width = fs.height = kSize;
    fs.stereo = mode;
    fs.cone_levels = 4;
    fs.count_evaluations = true;
    fs.lens_mask = lens;
    fs.foveation = foveation;
    HeadlessRenderer r(test::shared_context(), bulb(), fs, StereoSettings{kSize, kSize});
    return {r.render(kFilled, 0.0), r.views()};
}

std::uint32_t rgb(const Rgba8Image& image, std::size_t i) {
    return static_cast<std::uint32_t>(image.pixels[4 * i]) << 16 | static_cast<std::uint32_t>(image.pixels[4 * i + 1]) << 8 |
           image.pixels[4 * i + 2];
}

// Where the fovea ends, in pixels from the image centre, for a foveation radius in half heights.
double fovea_pixels(double radius) { return radius * 0.5 * kSize; }

class PixelBudget : public RuntimeTest, public ::testing::WithParamInterface<StereoMode> {};

std::string mode_name(const ::testing::TestParamInfo<StereoMode>& info) {
    std::string s = stereo_mode_name(info.param);
    for (auto& c : s)
        if (c == '-') c = '_';
    return s;
}

}  // namespace

TEST(FrameGraph, foveation_adds_one_fill_pass_per_eye_and_nothing_when_off) {
    FrameSettings s;
    s.width = s.height = 64;
    s.foveation = 0.0;
    FrameGraph off = FrameGraph::build(bulb().manifest, s, 80, 64);
    s.foveation = 0.5;
    FrameGraph on = FrameGraph::build(bulb().manifest, s, 80, 64);
    auto fovea_passes = [](const FrameGraph& g) {
        std::size_t n = 0;
        for (const auto& p : g.passes()) n += p.program == "fovea";
        return n;
    };
    EXPECT_EQ(fovea_passes(off), 0u) << off.describe();
    EXPECT_EQ(fovea_passes(on), 2u) << on.describe();
    EXPECT_NE(on.describe().find("foveation fovea radius 0.5"), std::string::npos) << on.describe();
    EXPECT_EQ(on.images().size(), off.images().size()) << "the fill works in place";
}

TEST(FrameGraph, a_scene_with_a_foveation_block_is_foveated_unless_the_user_turns_it_off) {
    Pack pack = test::compile_pack(R"({"format": "fractograph-graph", "version": 1, "name": "s",
      "nodes": [{"id": "ball", "type": "prim.sphere"}], "outputs": {"distance": "ball"},
      "scene": {"foveation": {"inner_radius": 0.4, "blend": 0.1}}})");
    FrameSettings s;
    s.width = s.height = 64;
    EXPECT_DOUBLE_EQ(FrameGraph::build(pack.manifest, s, 80, 64).settings.foveation, 0.4);
    s.foveation = 0.0;
    EXPECT_DOUBLE_EQ(FrameGraph::build(pack.manifest, s, 80, 64).settings.foveation, 0.0);
}

TEST_P(PixelBudget, the_lens_mask_blackens_only_hidden_pixels_and_leaves_the_rest_bit_identical) {
    Rendered full = render(GetParam(), false, 0.0);
    Rendered masked = render(GetParam(), true, 0.0);
    auto visible = visible_pixels(lens_ellipse(masked.views.left), kSize, kSize);
    std::size_t hidden = 0, changed = 0;
    for (std::size_t i = 0; i < visible.size(); ++i) {
        if (!visible[i]) {
            ++hidden;
            EXPECT_LT(masked.frame.depth_left[i], 0.0f) << "pixel " << i << " is hidden but was marched";
            EXPECT_EQ(rgb(masked.frame.left, i), 0u) << "pixel " << i << " is hidden but not black";
        } else {
            changed += masked.frame.depth_left[i] != full.frame.depth_left[i] || rgb(masked.frame.left, i) != rgb(full.frame.left, i);
        }
    }
    // An inscribed ellipse hides 1 - pi/4 of a square image.
    EXPECT_NEAR(static_cast<double>(hidden) / visible.size(), 1.0 - M_PI / 4.0, 0.02);
    EXPECT_EQ(changed, 0u);
    double saved = 1.0 - masked.frame.stats.evaluations_per_pixel / full.frame.stats.evaluations_per_pixel;
    RecordProperty("evaluations_saved", fmt::format("{:.1f}%", 100.0 * saved));
    EXPECT_GT(saved, 0.1) << "the mask saves no work";
}

TEST_P(PixelBudget, foveation_keeps_the_fovea_exact_and_the_periphery_close_to_ground_truth) {
    const double radius = 0.4;
    Rendered full = render(GetParam(), false, 0.0);
    Rendered fov = render(GetParam(), false, radius);
    auto cpu = test::cpu_scene(bulb());
    ReferenceSettings rs;
    rs.step_scale = bulb().manifest.find_spec("step_scale")->value;
    rs.epsilon = 0.05;
    rs.max_steps = 4000;
    auto truth = reference_depth(*cpu->evaluator, cpu->settings, fov.views.left, fov.views.pixel_half_diagonal, rs);

    std::size_t fovea = 0, fovea_changed = 0;
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x) {
            double r = std::hypot(x + 0.5 - 0.5 * kSize, y + 0.5 - 0.5 * kSize);
            if (r >= fovea_pixels(radius) - 1.0) continue;
            std::size_t i = static_cast<std::size_t>(y) * kSize + x;
            ++fovea;
            fovea_changed += fov.frame.depth_left[i] != full.frame.depth_left[i] || rgb(fov.frame.left, i) != rgb(full.frame.left, i);
        }
    EXPECT_GT(fovea, 500u);
    EXPECT_EQ(fovea_changed, 0u) << "inside the fovea every pixel is marched and shaded as without foveation";

    DepthComparison c_full = compare_depths(full.frame.depth_left, truth.depth, fov.views.pixel_half_diagonal);
    DepthComparison c_fov = compare_depths(fov.frame.depth_left, truth.depth, fov.views.pixel_half_diagonal);
    double saved = 1.0 - fov.frame.stats.evaluations_per_pixel / full.frame.stats.evaluations_per_pixel;
    double image_psnr = test::psnr(fov.frame.left, full.frame.left);
    RecordProperty("result", fmt::format("misclassified {:.2f}% (without foveation {:.2f}%), depth error median {:.2f} "
                                         "p95 {:.2f} cone radii (without {:.2f}, {:.2f}), {:.1f}% fewer evaluations, "
                                         "PSNR against the full image {:.1f} dB",
                                         100.0 * c_fov.misclassified, 100.0 * c_full.misclassified, c_fov.median_error,
                                         c_fov.p95_error, c_full.median_error, c_full.p95_error, 100.0 * saved,
                                         image_psnr));
    EXPECT_EQ(c_fov.not_finite, 0u);
    // A periphery pixel takes its block's depth: it can only be wrong on silhouettes, which the
    // filled view has many of.
    EXPECT_LE(c_fov.misclassified, c_full.misclassified + 0.06);
    EXPECT_LE(c_fov.median_error, 2.5 * c_full.median_error);
    EXPECT_GT(image_psnr, 18.0);
    // Reprojection marches the centre eye whole (it serves both lenses), so it saves less.
    EXPECT_GT(saved, GetParam() == StereoMode::Reproject ? 0.25 : 0.4)
        << "a quarter of the periphery should cost well under the whole of it";
}

INSTANTIATE_TEST_SUITE_P(EveryStereoMode, PixelBudget,
                         ::testing::Values(StereoMode::Naive, StereoMode::PerEye, StereoMode::Reproject), mode_name);

// The sequence benchmark counts the march's oversteps apart from the fill's (marched_pixels, the
// CPU's copy of fg_periphery): every visible pixel it calls filled holds the nearest hit among the
// marched pixels its colour blends, as the fovea pass fills it; the lens moves the fovea's centre,
// so the mask is on.
// At the image's size and at odd sizes, where the last column's or row's blocks lack their odd
// pixels and their corners clamp to the last even ones.
class FoveationFill : public RuntimeTest, public ::testing::WithParamInterface<std::pair<std::uint32_t, std::uint32_t>> {};

// The fovea pass's fill of the odd pixel (x, y) of a w x h eye: the nearest hit among the even
// corners of its block that its bilinear colour gives weight to, a miss where none of them hits.
float nearest_marched_hit(const std::vector<float>& depth, std::uint32_t w, std::uint32_t h, std::uint32_t x, std::uint32_t y) {
    std::uint32_t x0 = x & ~1u, y0 = y & ~1u, x1 = std::min(x0 + 2, (w - 1) & ~1u), y1 = std::min(y0 + 2, (h - 1) & ~1u);
    float nearest = -1.0f;
    for (std::uint32_t cy : {y0, y1})
        for (std::uint32_t cx : {x0, x1}) {
            bool weighted = (cx == x0 || (x & 1u)) && (cy == y0 || (y & 1u));
            float d = depth[cy * w + cx];
            if (weighted && d >= 0.0f && (nearest < 0.0f || d < nearest)) nearest = d;
        }
    return nearest;
}

TEST_P(FoveationFill, the_cpu_knows_which_pixels_take_their_depth_from_the_fill) {
    const auto [w, h] = GetParam();
    FrameSettings fs;
    fs.width = w;
    fs.height = h;
    fs.lens_mask = true;
    fs.foveation = 0.4;
    HeadlessRenderer r(test::shared_context(), bulb(), fs, StereoSettings{w, h});
    RenderedFrame f = r.render(kFilled, 0.0);
    // Silhouettes and the fovea's odd pixels scale with the image.
    const std::size_t some = std::size_t(100) * w * h / (kSize * kSize);
    for (int view : {kLeftView, kRightView}) {
        SCOPED_TRACE(view == kLeftView ? "left" : "right");
        const View& v = view == kLeftView ? r.views().left : r.views().right;
        const std::vector<std::uint8_t> seen = visible_pixels(lens_ellipse(v), w, h);
        const std::vector<std::uint8_t> marched = marched_pixels(r.executor().frame(), view);
        const std::vector<float>& depth = view == kLeftView ? f.depth_left : f.depth_right;
        std::size_t filled = 0, nearer_than_block = 0, odd_marched_unlike_fill = 0, edge_filled = 0;
        for (std::uint32_t y = 0; y < h; ++y)
            for (std::uint32_t x = 0; x < w; ++x) {
                std::size_t i = std::size_t(y) * w + x, block = std::size_t(y & ~1u) * w + (x & ~1u);
                if (!seen[i] || ((x | y) & 1u) == 0) continue;
                float fill = nearest_marched_hit(depth, w, h, x, y);
                if (!marched[i]) {
                    ++filled;
                    edge_filled += x + 1 == w || y + 1 == h;
                    EXPECT_EQ(depth[i], fill) << "pixel " << x << "," << y;
                    nearer_than_block += depth[i] >= 0.0f && (depth[block] < 0.0f || depth[i] < depth[block]);
                } else {
                    odd_marched_unlike_fill += depth[i] != fill;
                }
            }
        EXPECT_GT(filled, std::size_t(w) * h / 4) << "most of the periphery's odd pixels are filled";
        EXPECT_GT(nearer_than_block, some) << "silhouettes: the fill takes a nearer hit than the block's own";
        EXPECT_GT(odd_marched_unlike_fill, some) << "the fovea's odd pixels are marched, not filled";
        if (w % 2 == 1 || h % 2 == 1) EXPECT_GT(edge_filled, 0u) << "the last column or row has filled pixels";
    }
}

INSTANTIATE_TEST_SUITE_P(Sizes, FoveationFill,
                         ::testing::Values(std::pair<std::uint32_t, std::uint32_t>{kSize, kSize}, std::pair<std::uint32_t, std::uint32_t>{97, 75}),
                         [](const auto& info) { return fmt::format("{}x{}", info.param.first, info.param.second); });
