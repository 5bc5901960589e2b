// Dispatch constants (common/spec_constants.h) make one pipeline per case a pass runs: the
// conemarch's coarse levels and its level 0, the centre view and the eyes, each projection, frames
// with or without a lens and a fovea. They only drop code a dispatch never runs: frames are
// bit-identical to those of a pack whose manifest lists none (as an older fgc wrote it), whose
// shaders read the same values from their push constants and the frame's uniforms.
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

namespace {

// An eye's final image, rendered by an executor for `graph` from frames made with `frame`'s settings.
std::vector<std::byte> final_left(const Pack& pack, const FrameSettings& graph, const FrameSettings& frame) {
    StereoSettings stereo;
    stereo.width = graph.width;
    stereo.height = graph.height;
    StereoViews views = make_stereo_views(look_at({0.0, 0.55, 1.45}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}), Fov{-1.05, 0.8, -0.95, 0.7},
                                          Fov{-0.8, 1.05, -0.95, 0.7}, stereo);
    FrameExecutor executor(test::shared_context(), pack, FrameGraph::build(pack.manifest, graph, views.centre.width, views.centre.height));
    executor.set_frame(make_gpu_frame(views, frame, 0.0, 1.0, 0));
    executor.run();
    return executor.download("final.left");
}

}  // namespace

TEST_F(DispatchConstants, pipelines_without_a_lens_or_fovea_refuse_frames_with_one_and_a_headsets_lens_keeps_its_test) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    FrameSettings plain;
    plain.width = plain.height = 48;
    plain.foveation = 0.0;
    FrameSettings lens = plain;
    lens.lens_mask = true;
    // An OpenXR runtime's visibility mask reaches the frames without the user's lens mask: the
    // passes keep their lens test (FG_SPEC_LENS 1), so the frame is the lens mask's.
    FrameSettings headset = plain;
    headset.headset_lens = true;
    const std::vector<std::byte> masked = final_left(pack, lens, lens);
    EXPECT_EQ(final_left(pack, headset, lens), masked);
    EXPECT_NE(final_left(pack, plain, plain), masked) << "the lens hides pixels";
    // Pipelines made without a lens (or a fovea) would ignore one: such a frame is refused.
    EXPECT_THROW(final_left(pack, plain, lens), std::logic_error);
    FrameSettings foveated = plain;
    foveated.foveation = 0.5;
    EXPECT_THROW(final_left(pack, plain, foveated), std::logic_error);
}
