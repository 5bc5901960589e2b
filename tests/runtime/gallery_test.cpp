// Every gallery scene compiles, renders on lavapipe to a small stereo frame with nothing
// non-finite, shows the fractal in frame (neither an empty nor a solid view, unless the scene is a
// world you stand inside), and its hit mask agrees with the CPU twin traced with the pack's own rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <set>

#include "frame/accuracy_metrics.h"
#include "frame/cpu_reference_tracer.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 64;

std::vector<std::string> gallery_scenes() { return test::source_graph_names("graphs/gallery"); }

// Scenes that surround the camera: every ray may hit.
const std::set<std::string> kImmersive{"apollonian", "kleinian", "menger_twisted"};

class GalleryScene : public RuntimeTest, public ::testing::WithParamInterface<std::string> {};

}  // namespace

TEST(Gallery, has_at_least_ten_scenes) { EXPECT_GE(gallery_scenes().size(), 10u); }

TEST_P(GalleryScene, renders_in_frame_and_agrees_with_the_cpu_twin) {
    const std::string name = GetParam();
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/" + name + ".json"), "graphs/gallery");
    auto cpu = test::cpu_scene(pack);

    FrameSettings fs;
    fs.width = fs.height = kSize;
    fs.cone_levels = 3;
    HeadlessRenderer renderer(test::shared_context(), pack, fs, StereoSettings{});
    RenderedFrame frame = renderer.render(renderer.scene_camera(), 0.0);
    const StereoViews& views = renderer.views();

    ReferenceSettings rs;
    rs.step_scale = pack.manifest.find_spec("step_scale")->value;
    rs.epsilon = pack.manifest.find_spec("epsilon")->value;
    rs.max_steps = static_cast<int>(pack.manifest.find_spec("max_steps")->value);
    auto ref = reference_depth(*cpu->evaluator, cpu->settings, views.left, views.pixel_half_diagonal, rs);
    DepthComparison c = compare_depths(frame.depth_left, ref.depth, views.pixel_half_diagonal);

    double hit = static_cast<double>(c.both_hit + c.only_rendered) / static_cast<double>(c.pixels);
    std::string what = fmt::format("{}: hit {:.1f}% of the left eye, against the CPU twin misclassified {:.2f}% "
                                   "({} only rendered, {} only reference)",
                                   name, 100.0 * hit, 100.0 * c.misclassified, c.only_rendered, c.only_reference);
    SCOPED_TRACE(what);
    RecordProperty("figures", what);
    EXPECT_EQ(c.not_finite, 0u);
    for (float d : frame.depth_right) ASSERT_TRUE(std::isfinite(d)) << "right eye";
    EXPECT_GT(hit, kImmersive.count(name) ? 0.5 : 0.05) << "the fractal should fill a good part of the frame";
    if (!kImmersive.count(name)) EXPECT_LT(hit, 0.97) << "some sky should show around the fractal";
    // Float against double, at 64 px: a pixel on a silhouette may fall either way.
    EXPECT_LE(c.misclassified, 0.01);

    // Shading did something: the hit pixels are not one flat colour.
    std::set<std::uint32_t> colours;
    for (std::size_t i = 0; i < frame.depth_left.size(); ++i)
        if (frame.depth_left[i] >= 0.0f) {
            const std::uint8_t* px = frame.left.pixels.data() + i * 4;
            colours.insert((std::uint32_t(px[0]) << 16) | (std::uint32_t(px[1]) << 8) | px[2]);
        }
    EXPECT_GT(colours.size(), 20u);
}

INSTANTIATE_TEST_SUITE_P(Gallery, GalleryScene, ::testing::ValuesIn(gallery_scenes()),
                         [](const auto& info) { return info.param; });
