// Dispatch constants (common/spec_constants.h) make one pipeline per case a pass runs: the
// conemarch's coarse levels and its level 0, the centre view and the eyes, each projection. They
// only drop code a dispatch never runs: frames are bit-identical to those of a pack whose manifest
// lists none (as an older fgc wrote it), whose shaders read the same values from their push
// constants and the frame's uniforms.
#include <gtest/gtest.h>

#include "common/spec_constants.h"
#include "frame/frame_executor.h"
#include "frame/gpu_uniforms.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

class DispatchConstants : public RuntimeTest {};

Pack without_dispatch_constants(Pack pack) {
    for (auto& pass : pack.manifest.passes) pass.dispatch_constants.clear();
    return pack;
}

RenderedFrame render(const Pack& pack, StereoMode stereo, Projection projection) {
    FrameSettings fs;
    fs.width = 64;
    fs.height = projection == Projection::Perspective ? 48 : 32;
    fs.stereo = stereo;
    fs.projection = projection;
    fs.count_evaluations = true;
    HeadlessRenderer r(test::shared_context(), pack, fs, StereoSettings{});
    return r.render(look_at({0.0, 0.55, 1.45}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}), 0.0);
}

}  // namespace

TEST_F(DispatchConstants, the_pack_declares_them_and_frames_are_bit_identical_without) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    const ManifestPass* conemarch = pack.manifest.find_pass("conemarch");
    ASSERT_TRUE(conemarch);
    for (const auto& c : kDispatchConstants)
        EXPECT_NE(std::find(conemarch->dispatch_constants.begin(), conemarch->dispatch_constants.end(), c.id),
                  conemarch->dispatch_constants.end())
            << "conemarch does not declare " << c.glsl;
    Pack plain = without_dispatch_constants(pack);
    struct Case {
        const char* name;
        StereoMode stereo;
        Projection projection;
    };
    for (const Case& c : {Case{"per-eye", StereoMode::PerEye, Projection::Perspective},
                          Case{"reprojection (centre view)", StereoMode::Reproject, Projection::Perspective},
                          Case{"naive", StereoMode::Naive, Projection::Perspective},
                          Case{"ODS panorama", StereoMode::PerEye, Projection::Ods}}) {
        SCOPED_TRACE(c.name);
        RenderedFrame fast = render(pack, c.stereo, c.projection);
        RenderedFrame read = render(plain, c.stereo, c.projection);
        EXPECT_EQ(fast.depth_left, read.depth_left);
        EXPECT_EQ(fast.depth_right, read.depth_right);
        EXPECT_EQ(fast.left.pixels, read.left.pixels);
        EXPECT_EQ(fast.right.pixels, read.right.pixels);
        EXPECT_EQ(fast.stats.evaluations_per_pixel, read.stats.evaluations_per_pixel);
    }
}

TEST_F(DispatchConstants, a_frame_in_another_projection_than_the_pipelines_is_refused) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    FrameSettings fs;
    fs.width = 32;
    fs.height = 32;
    FrameExecutor executor(test::shared_context(), pack, FrameGraph::build(pack.manifest, fs, 32, 32));
    GpuFrame frame{};
    frame.projection = static_cast<std::uint32_t>(Projection::Ods);
    EXPECT_THROW(executor.set_frame(frame), std::logic_error);
}
