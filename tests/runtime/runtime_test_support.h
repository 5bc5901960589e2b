#pragma once
// Runtime tests render real frames on lavapipe with the validation layer on; a validation error
// fails the test. Packs are compiled from graph text by the real compiler.
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>

#include <vector>

#include "compiler.h"
#include "cpu/cpu_evaluator.h"
#include "frame/headless_renderer.h"
#include "pack/pack_reader.h"
#include "vk/context.h"

namespace fg::test {

std::string read_source_file(const std::string& relative);
// File stems of the graphs (*.json) in a source folder ("graphs/gallery"), sorted: a new file is a
// new test case without touching the tests.
std::vector<std::string> source_graph_names(const std::string& folder);
// Compiles graph text and reads the pack back, as fgplay would.
// `folder`: the source folder ("graphs/gallery") the graph reads its files from (an environment image).
Pack compile_pack(const std::string& graph_text, const std::string& folder = {});
// A size x size frame of one naive stereo pair with the AOVs, and a stereo rig whose left eye is the
// camera (no IPD): what tests that read a view's AOVs against closed forms render.
FrameSettings aov_frame(std::uint32_t size);
StereoSettings eye_at_camera(std::uint32_t size);
// Where the AOV image `name` is in aov_images() (and in a frame's aovs); std::logic_error if nowhere.
std::size_t aov_index(const std::string& name);
// The CPU twin of a pack's graph.
struct CpuScene {
    IrGraph ir;
    std::optional<CpuEvaluator> evaluator;
    SceneSettings settings;
};
std::unique_ptr<CpuScene> cpu_scene(const Pack& pack);

// The cone bound a conemarch level holds for full-resolution pixel (x, y), read from a downloaded
// atlas of a view `width` x `height` (layout: fg_level_rect in common.glsl, rg32f texels).
float atlas_cone_bound(const std::vector<std::byte>& atlas, std::uint32_t width, std::uint32_t height,
                       std::uint32_t level, std::uint32_t x, std::uint32_t y);

// The pass of a frame graph with this label; throws std::logic_error naming it when there is none.
FramePass& pass_named(FrameGraph& g, const std::string& label);
const FramePass& pass_named(const FrameGraph& g, const std::string& label);

// PSNR of two images' RGB against 255; 99 dB where they are equal.
double psnr(const Rgba8Image& a, const Rgba8Image& b);

// One Vulkan context for the whole test program (pipeline creation is the slow part on lavapipe).
vk::Context& shared_context();

class RuntimeTest : public ::testing::Test {
protected:
    void SetUp() override { errors_before_ = shared_context().validation_errors(); }
    void TearDown() override {
        EXPECT_EQ(shared_context().validation_errors(), errors_before_) << "Vulkan validation errors:\n"
                                                                          << validation_text();
    }
    static std::string validation_text();

private:
    std::size_t errors_before_ = 0;
};

}  // namespace fg::test
