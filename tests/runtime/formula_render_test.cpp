// Formula graphs on the GPU: each graph in graphs/formulas/ renders on lavapipe with its hit mask
// agreeing with the CPU twin (which interprets the same formula program the GLSL was written
// from), and where the gallery has the scene drawn with a hand-written node, the two 256² frames
// are at least 45 dB apart.
#include <gtest/gtest.h>

#include <filesystem>
#include <fmt/format.h>

#include "frame/accuracy_metrics.h"
#include "frame/cpu_reference_tracer.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

class FormulaGraph : public RuntimeTest, public ::testing::WithParamInterface<std::string> {};

RenderedFrame render(const Pack& pack, std::uint32_t size) {
    FrameSettings fs;
    fs.width = fs.height = size;
    fs.cone_levels = 3;
    HeadlessRenderer renderer(test::shared_context(), pack, fs, StereoSettings{});
    return renderer.render(renderer.scene_camera(), 0.0);
}

}  // namespace

TEST_P(FormulaGraph, renders_as_its_cpu_twin_traces_it_and_as_the_hand_written_node_does) {
    const std::string name = GetParam();
    Pack pack = test::compile_pack(test::read_source_file("graphs/formulas/" + name + ".json"));
    auto cpu = test::cpu_scene(pack);
    ASSERT_TRUE(cpu->evaluator);

    constexpr std::uint32_t kSize = 64;
    FrameSettings fs;
    fs.width = fs.height = kSize;
    fs.cone_levels = 3;
    HeadlessRenderer renderer(test::shared_context(), pack, fs, StereoSettings{});
    RenderedFrame frame = renderer.render(renderer.scene_camera(), 0.0);
    ReferenceSettings rs;
    rs.step_scale = pack.manifest.find_spec("step_scale")->value;
    rs.epsilon = pack.manifest.find_spec("epsilon")->value;
    rs.max_steps = static_cast<int>(pack.manifest.find_spec("max_steps")->value);
    const StereoViews& views = renderer.views();
    auto ref = reference_depth(*cpu->evaluator, cpu->settings, views.left, views.pixel_half_diagonal, rs);
    DepthComparison c = compare_depths(frame.depth_left, ref.depth, views.pixel_half_diagonal);
    double hit = static_cast<double>(c.both_hit + c.only_rendered) / static_cast<double>(c.pixels);
    SCOPED_TRACE(fmt::format("{}: hit {:.1f}%, misclassified against the CPU twin {:.2f}% ({} pixels hit only on the GPU, "
                             "{} only on the CPU)",
                             name, 100.0 * hit, 100.0 * c.misclassified, c.only_rendered, c.only_reference));
    EXPECT_EQ(c.not_finite, 0u);
    EXPECT_GT(hit, 0.05);
    // Float against double, at 64 px: a pixel on a silhouette may fall either way.
    EXPECT_LE(c.misclassified, 0.01);

    const std::string node_graph = "graphs/gallery/" + name + ".json";
    if (!std::filesystem::exists(std::string(FG_SOURCE_DIR) + "/" + node_graph)) return;
    Pack node_pack = test::compile_pack(test::read_source_file(node_graph));
    double db = test::psnr(render(pack, 256).left, render(node_pack, 256).left);
    RecordProperty("psnr_db", fmt::format("{:.1f}", db));
    EXPECT_GE(db, 45.0) << name << ": the formula graph's frame against the hand-written node's";
}

INSTANTIATE_TEST_SUITE_P(Formulas, FormulaGraph, ::testing::ValuesIn(test::source_graph_names("graphs/formulas")),
                         [](const auto& info) { return info.param; });
