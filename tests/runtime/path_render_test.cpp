// Offline rendering of a camera path: frames depend only on their number, so a range rendered in
// one run and the same range cut into shards (separate renderers, as separate job-array tasks
// would be) write identical files; --resume skips exactly the frames on disk that verify.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include "offline/frame_record.h"
#include "offline/path_render.h"
#include "offline/progress_bar.h"
#include "offline/supersample.h"
#include "offline_scene.h"
#include "runtime_test_support.h"
#include "scratch_dir.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

std::vector<char> file_bytes(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

class PathRender : public RuntimeTest {
protected:
    void SetUp() override {
        RuntimeTest::SetUp();
        scratch_ = std::make_unique<test::ScratchDir>("fg_path");
        dir_ = scratch_->path();
        Diagnostics diag;
        // Four frames at 3 fps over one second: a move forward, a turn to look at the ball, a zoom.
        auto json = nlohmann::json::parse(test::read_source_file("tests/runtime/data/short_path.json"));
        path_ = CameraPath::parse(json, 1.0, diag);
        ASSERT_TRUE(path_) << diag.format();
        settings_.projection = Projection::Ods;
        settings_.width = 64;
        settings_.height = 32;
    }
    void TearDown() override {
        scratch_.reset();
        RuntimeTest::TearDown();
    }
    PathRunResult run(const Pack& pack, const std::string& sub, FrameRange frames, bool resume = false) {
        PathRenderer renderer(test::shared_context(), pack, *path_, settings_);
        return run_path(renderer, {(dir_ / sub).string(), frames, "test job", resume, false});
    }

    std::unique_ptr<test::ScratchDir> scratch_;
    std::filesystem::path dir_;
    std::optional<CameraPath> path_;
    PathRenderSettings settings_;
};

class PathShards : public PathRender, public ::testing::WithParamInterface<Projection> {};

}  // namespace

// Every projection, the cone-marched ones included; equirect also supersampled.
TEST_P(PathShards, a_path_rendered_as_one_range_and_as_two_shards_writes_identical_files) {
    settings_.projection = GetParam();
    if (settings_.projection == Projection::Equirect) settings_.supersample = 2;
    if (settings_.projection == Projection::Perspective) settings_.width = 32;
    Pack pack = test::compile_pack(test::room_graph());
    ASSERT_EQ(path_->frame_count(), 4);
    FrameRange all{0, 4};
    run(pack, "whole", all);
    // The second shard first: order and process do not matter.
    run(pack, "shards", shard_of(all, 1, 2));
    run(pack, "shards", shard_of(all, 0, 2));
    for (int f = 0; f < 4; ++f) {
        auto whole = file_bytes(frame_image_path((dir_ / "whole").string(), f));
        auto shard = file_bytes(frame_image_path((dir_ / "shards").string(), f));
        ASSERT_FALSE(whole.empty()) << "frame " << f;
        EXPECT_EQ(whole, shard) << "frame " << f;
        EXPECT_EQ(file_bytes(frame_record_path(frame_image_path((dir_ / "whole").string(), f))),
                  file_bytes(frame_record_path(frame_image_path((dir_ / "shards").string(), f))));
    }
    // The camera moves: consecutive frames differ.
    EXPECT_NE(file_bytes(frame_image_path((dir_ / "whole").string(), 0)),
              file_bytes(frame_image_path((dir_ / "whole").string(), 1)));
}

// Jittered samples of a panorama move each pixel's point as --supersample's grid does: 4 samples
// give the picture of 2x2 supersampling (naive tracing, so the march does not depend on the grid).
TEST_F(PathRender, four_jittered_samples_of_an_ods_panorama_give_the_picture_of_2x2_supersampling) {
    settings_.stereo = StereoMode::Naive;
    Pack pack = test::compile_pack(test::room_graph());
    auto picture = [&](std::uint32_t supersample, std::uint32_t samples) {
        PathRenderSettings s = settings_;
        s.supersample = supersample;
        s.samples = samples;
        return PathRenderer(test::shared_context(), pack, *path_, s).render(1);
    };
    const Rgba8Image one = picture(1, 1), four = picture(1, 4), grid = picture(2, 1);
    const double p4 = test::psnr(four, grid), p1 = test::psnr(one, grid);
    EXPECT_GE(p4, 45.0) << "4 samples " << p4 << " dB, 1 sample " << p1 << " dB";
    EXPECT_GT(p4, p1 + 5.0) << "4 samples " << p4 << " dB, 1 sample " << p1 << " dB";
}

INSTANTIATE_TEST_SUITE_P(Projections, PathShards,
                         ::testing::Values(Projection::Ods, Projection::Equirect, Projection::Perspective),
                         [](const auto& info) { return std::string(projection_name(info.param)); });

TEST_F(PathRender, resume_skips_verified_frames_and_renders_missing_or_corrupted_ones_again) {
    Pack pack = test::compile_pack(test::room_graph());
    FrameRange all{0, 4};
    auto first = run(pack, "out", all);
    EXPECT_EQ(first.rendered, 4);
    auto frame = [&](int f) { return frame_image_path((dir_ / "out").string(), f); };
    auto good = file_bytes(frame(2));
    auto again = run(pack, "out", all, true);
    EXPECT_EQ(again.rendered, 0);
    EXPECT_EQ(again.skipped, 4);
    // A flipped byte in frame 2 (a damaged copy) and a lost frame 3.
    {
        std::fstream f(frame(2), std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(static_cast<std::streamoff>(good.size() / 2));
        f.put(static_cast<char>(good[good.size() / 2] ^ 0x40));
    }
    std::filesystem::remove(frame(3));
    auto repaired = run(pack, "out", all, true);
    EXPECT_EQ(repaired.rendered, 2);
    EXPECT_EQ(repaired.skipped, 2);
    EXPECT_EQ(file_bytes(frame(2)), good);
    // Another job (other pack, path or settings) does not count as done.
    PathRenderer renderer(test::shared_context(), pack, *path_, settings_);
    auto other = run_path(renderer, {(dir_ / "out").string(), {0, 1}, "another job", true, false});
    EXPECT_EQ(other.rendered, 1);
}

TEST(Supersampling, averages_samples_in_linear_light) {
    // Two black and two white samples are half the light: sRGB 188, not 128.
    Rgba8Image img{2, 2, {0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255}};
    Rgba8Image out = downsample(img, 2);
    ASSERT_EQ(out.width, 1u);
    ASSERT_EQ(out.height, 1u);
    EXPECT_EQ(out.pixels, (std::vector<std::uint8_t>{188, 188, 188, 255}));
}

TEST(ProgressBar, a_batch_log_gets_lines_with_frames_done_speed_and_time_left) {
    std::FILE* log = std::tmpfile();
    ASSERT_NE(log, nullptr);
    {
        ProgressBar bar(3, log);
        bar.advance(true);
        bar.advance(false);
        bar.advance(false);
        bar.finish();
    }
    std::rewind(log);
    std::string text;
    for (int c; (c = std::fgetc(log)) != EOF;) text += static_cast<char>(c);
    std::fclose(log);
    // Not a terminal: whole lines, no carriage returns, the last one complete.
    EXPECT_EQ(text.find('\r'), std::string::npos) << text;
    EXPECT_NE(text.find("0/3 frames"), std::string::npos) << text;
    EXPECT_NE(text.find("[##############################] 3/3 frames"), std::string::npos) << text;
    EXPECT_NE(text.find("fps, 0:00 left (1 already done)"), std::string::npos) << text;
}
