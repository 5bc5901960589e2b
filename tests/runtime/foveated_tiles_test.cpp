// An eye's passes dispatch only the 8x8 tiles that hold their pixels (dispatch_tiles.h,
// shaders/dispatch_tiles.glsl): foveated, the fovea's passes and its conemarch level 1 the tiles
// short of the periphery, the periphery's the tiles beyond, the fovea pass the tiles it fills; and
// once the images hold the miss of the pixels the lens hides, no pass dispatches the tiles wholly
// outside it. A CPU rasteriser runs a whole shader for a SIMD group whose lanes have nothing to do.
// A list must hold every pixel the shader takes, and frames must be bit-identical to dispatches
// over the whole image, also for a headset's off-centre lenses, where the lists follow the lens
// centre, and over many frames while the lens moves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "frame/dispatch_tiles.h"
#include "frame/frame_executor.h"
#include "frame/gpu_uniforms.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::pass_named;
using fg::test::RuntimeTest;

namespace {

class FoveatedTiles : public RuntimeTest {};

constexpr std::uint32_t kWidth = 160, kHeight = 120;

FrameSettings foveated(StereoMode stereo, bool tiles) {
    FrameSettings fs;
    fs.width = kWidth;
    fs.height = kHeight;
    fs.stereo = stereo;
    fs.lens_mask = true;
    fs.foveation = 0.4;
    fs.tile_dispatch = tiles;
    fs.count_evaluations = true;
    return fs;
}

struct Frame {
    std::vector<std::byte> left, right, depth_left, depth_right;
    double evaluations_per_pixel = 0.0;
};

// Both eyes through lenses whose centres sit off the image centre, as a headset's do (the
// left lens's towards the nose: the image's right).
StereoViews headset_views(const HeadPose& head, const FrameSettings& fs) {
    StereoSettings stereo;
    stereo.width = fs.width;
    stereo.height = fs.height;
    return make_stereo_views(head, Fov{-1.05, 0.8, -0.95, 0.7}, Fov{-0.8, 1.05, -0.95, 0.7}, stereo);
}

Frame run_frame(FrameExecutor& executor, const GpuFrame& gpu) {
    executor.set_frame(gpu);
    Frame f;
    f.evaluations_per_pixel = executor.run().evaluations_per_pixel;
    f.left = executor.download("final.left");
    f.right = executor.download("final.right");
    f.depth_left = executor.download("depth.left");
    f.depth_right = executor.download("depth.right");
    return f;
}

Frame render(const Pack& pack, const FrameSettings& fs) {
    StereoViews views = headset_views(look_at({0.0, 0.55, 1.45}, {0.0, 0.0, 0.0}), fs);
    FrameExecutor executor(test::shared_context(), pack,
                           FrameGraph::build(pack.manifest, fs, views.centre.width, views.centre.height));
    return run_frame(executor, make_gpu_frame(views, executor.graph().settings, 0.0, 1.0, 0));
}

// fg_periphery in common.glsl, in float as the shader computes it.
float periphery(const GpuFrame& f, int view, glm::ivec2 pixel) {
    const GpuView& v = f.views[view];
    glm::vec2 size(f.eye_size);
    glm::vec2 centre = (v.lens_radii.x > 0.0f ? v.lens_centre : glm::vec2(0.5f)) * size;
    float r = glm::length(glm::vec2(pixel) + 0.5f - centre) / (0.5f * size.y);
    return std::clamp((r - f.fovea_radius) / std::max(f.fovea_blend, 1e-6f), 0.0f, 1.0f);
}

GpuFrame frame_with(std::uint32_t w, std::uint32_t h, glm::vec2 lens_centre, float fovea, float blend) {
    GpuFrame f{};
    f.eye_size = {w, h};
    f.fovea_radius = fovea;
    f.fovea_blend = blend;
    for (auto& v : f.views) {
        v.lens_centre = lens_centre;
        v.lens_radii = {0.5f, 0.5f};
    }
    return f;
}

// fg_outside_lens in common.glsl, in float as the shader computes it: a pixel's centre, or a coarse
// cell's block centre against radii grown by the block.
bool outside_lens(const GpuFrame& f, int view, glm::vec2 centre_px, float block) {
    const GpuView& v = f.views[view];
    if (v.lens_radii.x <= 0.0f) return false;
    glm::vec2 size(f.eye_size);
    glm::vec2 margin = block > 1.0f ? glm::vec2(block) / size : glm::vec2(0.0f);
    glm::vec2 q = (centre_px / size - v.lens_centre) / (v.lens_radii + margin);
    return glm::dot(q, q) > 1.0f;
}

bool listed_in(const std::vector<std::uint32_t>& tiles, glm::ivec2 cell) {
    return std::count(tiles.begin(), tiles.end(), std::uint32_t(cell.x / 8) | std::uint32_t(cell.y / 8) << 16) == 1;
}

}  // namespace

TEST(DispatchTiles, every_pixel_a_pass_takes_inside_the_lens_lies_in_a_listed_tile_and_those_outside_are_left_out) {
    // A headset's lens ellipse towards the nose and one at the image's edge, an unfoveated eye (the
    // whole image) and foveated ones, odd sizes.
    struct Case {
        std::uint32_t w, h;
        glm::vec2 centre, radii;
        float fovea;
    };
    for (const Case& c : {Case{160, 120, {0.5f, 0.5f}, {0.5f, 0.5f}, 0.0f}, Case{257, 131, {0.57f, 0.46f}, {0.55f, 0.5f}, 0.5f},
                          Case{96, 96, {0.02f, 0.97f}, {0.5f, 0.4f}, 0.3f}, Case{512, 512, {0.53f, 0.5f}, {0.5f, 0.5f}, 0.0f}}) {
        SCOPED_TRACE(::testing::Message() << c.w << "x" << c.h << " centre " << c.centre.x << "," << c.centre.y
                                          << " fovea " << c.fovea);
        GpuFrame f = frame_with(c.w, c.h, c.centre, c.fovea, 0.15f);
        for (auto& v : f.views) v.lens_radii = c.radii;
        auto inside = [&](TileRegion region) { return list_dispatch_tiles(f, 0, region, OutsideLens::Left); };
        const auto whole = inside(TileRegion::Whole), fovea = inside(TileRegion::Fovea), level1 = inside(TileRegion::FoveaLevel1),
                   outer = inside(TileRegion::Periphery), fill = inside(TileRegion::Fill);
        std::size_t missing = 0, shown = 0;
        for (int y = 0; y < int(c.h); ++y)
            for (int x = 0; x < int(c.w); ++x) {
                glm::ivec2 p(x, y);
                glm::vec2 centre = glm::vec2(p) + 0.5f;
                if (!outside_lens(f, 0, centre, 1.0f)) {
                    ++shown;
                    if (c.fovea == 0.0f) missing += !listed_in(whole, p);
                    float s = periphery(f, 0, p);
                    if (c.fovea > 0.0f && s < 1.0f) missing += !listed_in(fovea, p);
                    if (c.fovea > 0.0f && s >= 1.0f && x % 2 == 0 && y % 2 == 0) missing += !listed_in(outer, p / 2);
                    if (c.fovea > 0.0f && s > 0.0f && ((x | y) & 1)) missing += !listed_in(fill, p / 2);
                }
                // A level-1 cell marches unless its block is outside the lens grown by the block.
                if (c.fovea > 0.0f && x % 2 == 0 && y % 2 == 0 && periphery(f, 0, p) < 1.0f &&
                    !outside_lens(f, 0, glm::vec2(p) + 1.0f, 2.0f))
                    missing += !listed_in(level1, p / 2);
            }
        EXPECT_EQ(missing, 0u);
        ASSERT_GT(shown, 0u);
        // What the lens leaves out: the tiles wholly outside the ellipse (an inscribed one hides 21 %
        // of the pixels; tiles across its edge stay).
        if (c.fovea == 0.0f) {
            const double all = double(dispatch_tile_capacity(c.w, c.h, TileRegion::Whole));
            EXPECT_EQ(list_dispatch_tiles(f, 0, TileRegion::Whole).size(), all);
            std::printf("%ux%u: %zu of %.0f tiles inside the lens\n", c.w, c.h, whole.size(), all);
            EXPECT_LT(whole.size(), (c.w >= 512 ? 0.84 : 0.93) * all);
            EXPECT_GT(whole.size(), double(shown) / 64.0);
        }
    }
}

TEST(DispatchTiles, every_pixel_a_pass_takes_lies_in_a_listed_tile_and_few_others_are_listed) {
    // A centred fovea, a headset's lens towards the nose, one at the image's edge, a fovea wider
    // than the image, odd sizes, and a blend of 0 (the shader divides by at least 1e-6).
    struct Case {
        std::uint32_t w, h;
        glm::vec2 centre;
        float fovea, blend;
    };
    for (const Case& c : {Case{160, 120, {0.5f, 0.5f}, 0.4f, 0.15f}, Case{257, 131, {0.57f, 0.46f}, 0.5f, 0.15f},
                          Case{96, 96, {0.02f, 0.97f}, 0.3f, 0.1f}, Case{64, 48, {0.5f, 0.5f}, 3.0f, 0.15f},
                          Case{200, 200, {0.43f, 0.5f}, 0.25f, 0.0f}}) {
        SCOPED_TRACE(::testing::Message() << c.w << "x" << c.h << " centre " << c.centre.x << "," << c.centre.y
                                          << " fovea " << c.fovea);
        GpuFrame f = frame_with(c.w, c.h, c.centre, c.fovea, c.blend);
        auto listed = [&](TileRegion region) {
            std::vector<std::uint32_t> tiles = list_dispatch_tiles(f, 0, region);
            EXPECT_LE(tiles.size(), dispatch_tile_capacity(c.w, c.h, region));
            return [tiles](glm::ivec2 cell) {
                return std::count(tiles.begin(), tiles.end(), std::uint32_t(cell.x / 8) | std::uint32_t(cell.y / 8) << 16) == 1;
            };
        };
        auto fovea = listed(TileRegion::Fovea), level1 = listed(TileRegion::FoveaLevel1),
             outer = listed(TileRegion::Periphery), fill = listed(TileRegion::Fill);
        std::size_t missing = 0, fovea_pixels = 0;
        for (int y = 0; y < int(c.h); ++y)
            for (int x = 0; x < int(c.w); ++x) {
                glm::ivec2 p(x, y);
                float s = periphery(f, 0, p);
                if (s < 1.0f) {
                    // A fovea pixel, and the level-1 cell it starts from.
                    ++fovea_pixels;
                    missing += !fovea(p) + !level1(p / 2);
                } else if (x % 2 == 0 && y % 2 == 0) {
                    missing += !outer(p / 2);
                }
                if (s > 0.0f && ((x | y) & 1)) missing += !fill(p / 2);   // the fill's cells are 2x2 blocks
            }
        EXPECT_EQ(missing, 0u);
        // Tight: a listed fovea tile holds a pixel within 2 pixels of the fovea's edge; without a
        // periphery nothing is listed for it.
        const float edge = (c.fovea + std::max(c.blend, 1e-6f)) * 0.5f * float(c.h) + 2.0f;
        const glm::vec2 centre = c.centre * glm::vec2(c.w, c.h);
        for (std::uint32_t t : list_dispatch_tiles(f, 0, TileRegion::Fovea)) {
            bool near = false;
            for (std::uint32_t y = (t >> 16) * 8; y < std::min((t >> 16) * 8 + 8, c.h); ++y)
                for (std::uint32_t x = (t & 0xffff) * 8; x < std::min((t & 0xffff) * 8 + 8, c.w); ++x)
                    near = near || glm::length(glm::vec2(x, y) + 0.5f - centre) < edge;
            EXPECT_TRUE(near) << "tile " << (t & 0xffff) << "," << (t >> 16);
        }
        if (fovea_pixels == std::size_t(c.w) * c.h) EXPECT_TRUE(list_dispatch_tiles(f, 0, TileRegion::Periphery).empty());
    }
}

TEST_F(FoveatedTiles, a_foveated_eyes_passes_dispatch_their_tiles_and_nothing_else_does) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    FrameGraph g = FrameGraph::build(pack.manifest, foveated(StereoMode::PerEye, true), kWidth, kHeight);
    const std::pair<const char*, const char*> expected[] = {
        {"conemarch.left.L0", "tiles.left.fovea"},         {"shade.left", "tiles.left.fovea"},
        {"conemarch.right.L0", "tiles.right.fovea"},       {"conemarch.left.L0.periphery", "tiles.left.periphery"},
        {"shade.right.periphery", "tiles.right.periphery"}, {"conemarch.left.L1", "tiles.left.fovea_L1"},
        {"fovea.left", "tiles.left.fill"}};
    for (const auto& [label, tiles] : expected) {
        SCOPED_TRACE(label);
        const FramePass& p = pass_named(g, label);
        EXPECT_EQ(p.tile_list, tiles);
        EXPECT_EQ(p.specialize.at(kSpecTileList.id), 1);
        EXPECT_TRUE(p.reads_resource(tiles));
        ASSERT_NE(g.find_buffer(tiles), nullptr);
    }
    // The coarser levels are small and whole; the periphery's pixels start from level 2.
    EXPECT_TRUE(pass_named(g, "conemarch.left.L2").tile_list.empty());
    EXPECT_EQ(pass_named(g, "conemarch.left.L0.periphery").specialize.at(kSpecPeripheryParent.id), 2);
    FrameSettings reuse = foveated(StereoMode::PerEye, true);
    reuse.knobs["reuse"] = 1.0;   // walks every cell of the old level 1: it is marched whole, and the periphery starts there
    FrameGraph with_reuse = FrameGraph::build(pack.manifest, reuse, kWidth, kHeight);
    EXPECT_TRUE(pass_named(with_reuse, "conemarch.left.L1").tile_list.empty());
    EXPECT_FALSE(pass_named(with_reuse, "conemarch.left.L0.periphery").specialize.count(kSpecPeripheryParent.id));
    FrameGraph whole = FrameGraph::build(pack.manifest, foveated(StereoMode::PerEye, false), kWidth, kHeight);
    EXPECT_TRUE(pass_named(whole, "shade.left").tile_list.empty());
    EXPECT_EQ(pass_named(whole, "shade.left").invocations, (std::array<std::uint32_t, 3>{kWidth, kHeight, 1}));
    // A pack whose shaders cannot map tiles (an older fgc's) dispatches the whole image.
    for (auto& pass : pack.manifest.passes) std::erase(pass.dispatch_constants, kSpecTileList.id);
    FrameGraph old = FrameGraph::build(pack.manifest, foveated(StereoMode::PerEye, true), kWidth, kHeight);
    for (const FramePass& p : old.passes()) EXPECT_TRUE(p.tile_list.empty()) << p.label;
}

// Frames of one executor, the head moving, each frame through its own lens ellipse (a headset's
// visibility mask can change, and the lists must follow it): the final image and depth of each.
std::vector<Frame> render_sequence(const Pack& pack, const FrameSettings& fs, const std::vector<glm::vec4>& lenses) {
    StereoViews first = headset_views(look_at({0.0, 0.55, 1.55}, {0.0, 0.0, 0.0}), fs);
    FrameExecutor executor(test::shared_context(), pack,
                           FrameGraph::build(pack.manifest, fs, first.centre.width, first.centre.height));
    std::vector<Frame> frames;
    for (std::size_t i = 0; i < lenses.size(); ++i) {
        double a = 0.02 * double(i);
        StereoViews views = headset_views(look_at({std::sin(a) * 1.55, 0.55, std::cos(a) * 1.55}, {0.0, 0.0, 0.0}), fs);
        GpuFrame gpu = make_gpu_frame(views, executor.graph().settings, 0.0, 1.0, static_cast<std::uint32_t>(i));
        for (auto& v : gpu.views) {
            v.lens_centre = {lenses[i].x, lenses[i].y};
            v.lens_radii = {lenses[i].z, lenses[i].w};
        }
        frames.push_back(run_frame(executor, gpu));
    }
    return frames;
}

TEST_F(FoveatedTiles, frames_through_a_lens_leave_out_its_hidden_tiles_and_stay_bit_identical_while_it_moves) {
    // Four frames through one lens (the lists leave its outside out from the second, or the third
    // with history images), then a narrower lens off centre, the mask off, and the first lens again:
    // every pixel a list left out must still hold what a dispatch over the whole image writes.
    std::vector<glm::vec4> lenses(4, glm::vec4(0.5f, 0.5f, 0.5f, 0.5f));
    for (glm::vec4 l : {glm::vec4(0.56f, 0.47f, 0.42f, 0.4f), glm::vec4(0.56f, 0.47f, 0.42f, 0.4f), glm::vec4(0.56f, 0.47f, 0.42f, 0.4f),
                        glm::vec4(0.5f, 0.5f, 0.0f, 0.0f), glm::vec4(0.5f, 0.5f, 0.0f, 0.0f), glm::vec4(0.5f, 0.5f, 0.5f, 0.5f),
                        glm::vec4(0.5f, 0.5f, 0.5f, 0.5f), glm::vec4(0.5f, 0.5f, 0.5f, 0.5f)})
        lenses.push_back(l);
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    struct Case {
        const char* name;
        StereoMode stereo;
        double foveation;
        double shade_history;
    };
    for (const Case& c : {Case{"per-eye", StereoMode::PerEye, 0.0, 0.0}, Case{"naive", StereoMode::Naive, 0.0, 0.0},
                          Case{"reproject", StereoMode::Reproject, 0.0, 0.0},
                          Case{"per-eye, foveated", StereoMode::PerEye, 0.4, 0.0},
                          Case{"per-eye, shading history", StereoMode::PerEye, 0.0, 0.5}}) {
        SCOPED_TRACE(c.name);
        FrameSettings fs = foveated(c.stereo, true);
        fs.width = 96;
        fs.height = 80;
        fs.foveation = c.foveation;
        if (c.shade_history > 0.0) fs.knobs["shade_history"] = c.shade_history;
        FrameGraph g = FrameGraph::build(pack.manifest, fs, fs.width, fs.height);
        if (c.foveation == 0.0) EXPECT_EQ(pass_named(g, "shade.left").tile_list, "tiles.left.whole");
        if (c.stereo == StereoMode::Reproject) EXPECT_TRUE(pass_named(g, "conemarch.centre.L0").tile_list.empty());
        FrameSettings whole_fs = fs;
        whole_fs.tile_dispatch = false;
        std::vector<Frame> tiled = render_sequence(pack, fs, lenses), whole = render_sequence(pack, whole_fs, lenses);
        for (std::size_t i = 0; i < lenses.size(); ++i) {
            SCOPED_TRACE(::testing::Message() << "frame " << i);
            EXPECT_TRUE(tiled[i].left == whole[i].left);
            EXPECT_TRUE(tiled[i].right == whole[i].right);
            EXPECT_TRUE(tiled[i].depth_left == whole[i].depth_left);
            EXPECT_TRUE(tiled[i].depth_right == whole[i].depth_right);
        }
    }
}

TEST_F(FoveatedTiles, frames_are_bit_identical_to_dispatches_over_the_whole_image) {
    // The bulb shades straight into the final image; the KIFS's glow adds the post pass.
    for (const char* graph : {"graphs/gallery/mandelbulb.json", "graphs/gallery/kifs.json"}) {
        Pack pack = test::compile_pack(test::read_source_file(graph));
        for (StereoMode stereo : {StereoMode::Naive, StereoMode::PerEye, StereoMode::Reproject}) {
            SCOPED_TRACE(std::string(graph) + " " + stereo_mode_name(stereo));
            Frame tiled = render(pack, foveated(stereo, true));
            Frame whole = render(pack, foveated(stereo, false));
            EXPECT_TRUE(tiled.left == whole.left);
            EXPECT_TRUE(tiled.right == whole.right);
            EXPECT_TRUE(tiled.depth_left == whole.depth_left);
            EXPECT_TRUE(tiled.depth_right == whole.depth_right);
            // The same rays; per-eye, level 1 no longer marches the periphery's cells, which no pixel reads.
            if (stereo == StereoMode::PerEye) EXPECT_LT(tiled.evaluations_per_pixel, whole.evaluations_per_pixel);
            else EXPECT_EQ(tiled.evaluations_per_pixel, whole.evaluations_per_pixel);
        }
    }
}

TEST(DispatchTiles, a_list_longer_than_a_dispatch_row_goes_in_padded_rows) {
    // An 8K eye has 524,288 tiles; Vulkan promises only 65,535 workgroups along x.
    GpuFrame f = frame_with(8192, 4096, {0.5f, 0.5f}, 0.0f, 0.15f);
    std::vector<std::uint32_t> tiles = list_dispatch_tiles(f, 0, TileRegion::Whole);
    auto groups = tile_dispatch_groups(tiles.size());
    EXPECT_EQ(groups[0], kTileRow);
    EXPECT_EQ(groups[1], 9u);
    EXPECT_EQ(tiles.size(), std::size_t(groups[0]) * groups[1]);
    EXPECT_LE(tiles.size(), dispatch_tile_capacity(8192, 4096, TileRegion::Whole));
    EXPECT_EQ(std::count(tiles.begin(), tiles.end(), kNoTile), std::ptrdiff_t(tiles.size()) - 524288);
    EXPECT_EQ(tiles[524287], 1023u | 511u << 16);
    // A short list is one row, unpadded.
    EXPECT_EQ(tile_dispatch_groups(4096), (std::array<std::uint32_t, 3>{4096, 1, 1}));
    EXPECT_EQ(tile_dispatch_groups(0)[0], 0u);
}

TEST_F(FoveatedTiles, an_eye_of_more_tiles_than_a_dispatch_row_renders_every_row) {
    // 2048x2056 per eye: 65,792 tiles, two rows of workgroups. Looking away from the bulb, so every
    // ray leaves the bounds at once and the frame stays cheap; the lens leaves a fifth out.
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    FrameSettings fs;
    fs.width = 2048;
    fs.height = 2056;
    fs.lens_mask = true;
    FrameGraph g = FrameGraph::build(pack.manifest, fs, fs.width, fs.height);
    ASSERT_EQ(pass_named(g, "shade.left").tile_list, "tiles.left.whole");
    StereoSettings stereo;
    stereo.width = fs.width;
    stereo.height = fs.height;
    const Fov fov{-1.0, 1.0, -1.0, 1.0};
    StereoViews views = make_stereo_views(look_at({0.0, 0.0, 3.0}, {0.0, 0.0, 6.0}), fov, fov, stereo);
    auto render_twice = [&](bool tiles) {
        FrameSettings s = fs;
        s.tile_dispatch = tiles;
        FrameExecutor executor(test::shared_context(), pack, FrameGraph::build(pack.manifest, s, views.centre.width, views.centre.height));
        GpuFrame gpu = make_gpu_frame(views, executor.graph().settings, 0.0, 1.0, 0);
        // Without the lens in the second frame, every tile of both rows is dispatched again.
        executor.set_frame(gpu);
        executor.run();
        std::vector<std::byte> lens = executor.download("final.left");
        for (auto& v : gpu.views) v.lens_radii = {0.0f, 0.0f};
        executor.set_frame(gpu);
        executor.run();
        return std::pair{lens, executor.download("final.left")};
    };
    auto tiled = render_twice(true), whole = render_twice(false);
    EXPECT_TRUE(tiled.first == whole.first);
    EXPECT_TRUE(tiled.second == whole.second);
    // The last pixel lies in the second row's tiles: the background, not the cleared image's zeros.
    EXPECT_NE(std::to_integer<int>(tiled.second[tiled.second.size() - 1]), 0);
}
