// The head traces' trade-offs (bench/sequence_trade_offs.h): what `fgplay bench --sequence` writes
// for the frame governor is read back by the same reader `fgplay xr --trade-offs` uses, with each
// setting's cost summed over the traces, its knobs kept, and a setting that failed on any trace left
// out.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "frame/trade_off_front.h"
#include "frame/trade_off_ladder.h"
#include "scratch_dir.h"
#include "sequence_settings.h"
#include "sequence_trade_offs.h"

namespace fg::bench {
namespace {

constexpr std::uint32_t kSize = 128;

// A row of `frames` rendered frames, each taking `ms` and misclassifying `wrong` percent (NaN: its
// depths not compared), its picture `picture_db` from the ground truth (by default the worse, the
// more pixels are wrong).
SequenceRow row(const std::string& scene, const std::string& trace, const SequenceSetting& setting, double ms,
                double wrong, int frames = 3, double picture_db = -1.0) {
    SequenceRow r;
    r.scene = scene;
    r.trace = trace;
    r.setting = setting;
    for (int i = 0; i < frames; ++i) {
        SequenceFrame f;
        f.index = i;
        f.gpu_ms = ms;
        f.compared = true;
        f.depths_compared = !std::isnan(wrong);
        f.misclassified_pct = wrong;
        f.picture_psnr = picture_db >= 0.0 ? picture_db : 50.0 - 20.0 * wrong;
        r.frames.push_back(f);
    }
    r.summarize();
    return r;
}

const SequenceSetting& setting(const std::vector<SequenceSetting>& all, const std::string& name) {
    for (const auto& s : all)
        if (s.name() == name) return s;
    throw std::runtime_error("no setting " + name);
}

TEST(SequenceTradeOffs, the_governor_reads_each_settings_cost_summed_over_the_traces_and_skips_failures) {
    const auto settings = make_sequence_settings(kSize, false);
    const std::string masked = std::string("per-eye with ") + kMaskedPixels;
    SequenceReport report;
    report.size = kSize;
    report.device = "test";
    for (const char* trace : {"look_around", "walk"}) {
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "naive"), 40.0, 0.20));
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "per-eye"), 30.0, 0.25));
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "per-eye + persistent lanes"), 20.0, 0.25));
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "per-eye + reuse"), 35.0, 0.25));   // beaten
        report.rows.push_back(row("mandelbulb", trace, setting(settings, masked), 10.0, 0.40));
        // Another scene's rows are not this scene's trade-offs.
        report.rows.push_back(row("kleinian", trace, setting(settings, "naive"), 1.0, 0.0));
    }
    // Cheap and exact, but it failed on one trace: it cannot be trusted on the other.
    SequenceRow failed = row("mandelbulb", "look_around", setting(settings, "per-eye + shading history"), 5.0, 0.0);
    failed.error = "device lost";
    report.rows.push_back(failed);
    report.rows.push_back(row("mandelbulb", "walk", setting(settings, "per-eye + shading history"), 5.0, 0.0));
    // All dark on one trace: no time measured, so not on the front either.
    report.rows.push_back(row("mandelbulb", "look_around", setting(settings, "naive + persistent lanes"), 0.0, 0.0, 0));
    report.rows.push_back(row("mandelbulb", "walk", setting(settings, "naive + persistent lanes"), 8.0, 0.0));

    const nlohmann::json j = sequence_trade_offs_json(report, "mandelbulb");
    test::ScratchDir dir{"fg_sequence_trade_offs"};
    std::ofstream(dir / "trade_offs_mandelbulb.json") << j.dump(1);
    const std::vector<TradeOff> front = read_trade_offs((dir / "trade_offs_mandelbulb.json").string());

    ASSERT_EQ(front.size(), 3u) << j["trade_offs"].dump();
    EXPECT_EQ(front[0].setting, masked);
    EXPECT_DOUBLE_EQ(front[0].time_ms, 20.0);
    EXPECT_DOUBLE_EQ(front[0].wrong_pct, 0.40);
    EXPECT_TRUE(front[0].frame.lens_mask);
    EXPECT_DOUBLE_EQ(front[0].frame.foveation, 0.5);
    EXPECT_EQ(front[1].setting, "per-eye + persistent lanes");
    EXPECT_DOUBLE_EQ(front[1].time_ms, 40.0);
    EXPECT_EQ(front[1].frame.stereo, StereoMode::PerEye);
    EXPECT_EQ(front[1].frame.knobs.at("persistent_lanes"), 1.0);
    EXPECT_EQ(front[2].setting, "naive");
    EXPECT_EQ(front[2].frame.stereo, StereoMode::Naive);
    EXPECT_DOUBLE_EQ(front[2].render_scale, 1.0);
    EXPECT_EQ(j["trade_offs"].size(), 3u);
    EXPECT_EQ(j["rows"].size(), 14u);   // the bulb's only
}

TEST(SequenceTradeOffs, anti_aliasing_earns_its_rung_by_the_pictures_error) {
    // TAA marches as per-eye does (the same pixels wrong) but its picture is closer to the ground
    // truth: with the picture's error measured, it is on the front between per-eye and naive.
    const auto settings = make_sequence_settings(kSize, true);
    SequenceReport report;
    report.size = kSize;
    for (const char* trace : {"look_around", "walk"}) {
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "naive"), 40.0, 0.20, 3, 30.0));
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "per-eye"), 30.0, 0.25, 3, 29.0));
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "per-eye + TAA"), 33.0, 0.25, 3, 33.0));
    }
    const nlohmann::json j = sequence_trade_offs_json(report, "mandelbulb");
    test::ScratchDir dir{"fg_sequence_trade_offs_taa"};
    std::ofstream(dir / "trade_offs_mandelbulb.json") << j.dump(1);
    const std::vector<TradeOff> front = read_trade_offs((dir / "trade_offs_mandelbulb.json").string());
    ASSERT_EQ(front.size(), 2u) << j["trade_offs"].dump();
    EXPECT_EQ(front[0].setting, "per-eye");
    EXPECT_EQ(front[1].setting, "per-eye + TAA");
    EXPECT_TRUE(front[1].frame.taa);
    EXPECT_NEAR(j["trade_offs"][1]["picture_psnr_db"].get<double>(), 33.0, 1e-9);
}

TEST(SequenceTradeOffs, temporal_upsampling_is_judged_by_its_picture_and_keeps_its_factor) {
    // TAAU marches fewer pixels than the reference: its depths are not compared, only its picture.
    const auto settings = make_sequence_settings(kSize, true);
    const double unmeasured = std::numeric_limits<double>::quiet_NaN();
    SequenceReport report;
    report.size = kSize;
    for (const char* trace : {"look_around", "walk"}) {
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "per-eye"), 30.0, 0.25, 3, 29.0));
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "per-eye + TAA"), 33.0, 0.25, 3, 33.0));
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "per-eye + TAAU 2"), 12.0, unmeasured, 3, 29.5));
        report.rows.push_back(row("mandelbulb", trace, setting(settings, "per-eye + TAAU 1.5"), 31.0, unmeasured, 3, 30.0));
    }
    const nlohmann::json j = sequence_trade_offs_json(report, "mandelbulb");
    test::ScratchDir dir{"fg_sequence_trade_offs_taau"};
    std::ofstream(dir / "trade_offs_mandelbulb.json") << j.dump(1);
    const std::vector<TradeOff> front = read_trade_offs((dir / "trade_offs_mandelbulb.json").string());
    // Per-eye costs more than TAAU 2 for a worse picture, TAAU 1.5 more than TAAU 2 for less than TAA.
    ASSERT_EQ(front.size(), 3u) << j["trade_offs"].dump();
    EXPECT_EQ(front[0].setting, "per-eye + TAAU 2");
    EXPECT_EQ(front[1].setting, "per-eye + TAAU 1.5");
    EXPECT_EQ(front[2].setting, "per-eye + TAA");
    EXPECT_TRUE(j["trade_offs"][0]["wrong_pct"].is_null());
    EXPECT_DOUBLE_EQ(front[0].taa_upscale, 2.0);
    EXPECT_DOUBLE_EQ(front[0].render_scale, 1.0);
    EXPECT_DOUBLE_EQ(front[2].taa_upscale, 1.0);
    // The governor's level marches a quarter of the pixels and shows all of them.
    const GovernorLevel level = trade_off_ladder(PackManifest{}, front).back();
    FrameSettings full;
    const FrameSettings f = settings_at_level(full, level, 96, 96);
    EXPECT_TRUE(f.taa);
    EXPECT_EQ(f.width, 48u);
    EXPECT_EQ(f.shown_width(), 96u);
    EXPECT_DOUBLE_EQ(f.detail_scale, 0.5);
}

TEST(SequenceTradeOffs, a_scene_with_no_setting_measured_on_every_trace_says_why_it_has_no_front) {
    const auto settings = make_sequence_settings(kSize, true);
    SequenceReport report;
    report.size = kSize;
    SequenceRow r = row("mandelbox", "walk", setting(settings, "per-eye"), 10.0, 0.1);
    r.error = "out of memory";
    report.rows.push_back(r);
    const nlohmann::json j = sequence_trade_offs_json(report, "mandelbox");
    EXPECT_TRUE(j["trade_offs"].empty());
    EXPECT_NE(j.value("front_error", std::string()).find("no setting was measured without error"), std::string::npos)
        << j.dump();
}

}  // namespace
}  // namespace fg::bench
