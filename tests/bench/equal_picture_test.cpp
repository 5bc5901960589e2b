// The head traces' headline (bench/equal_picture.h): the cheapest setting at naive 1 spp's picture
// is picked per scene, trace and pixel set, never from a failed row, and "none" where nothing
// reaches it.
#include <gtest/gtest.h>

#include "equal_picture.h"
#include "sequence_settings.h"

namespace fg::bench {
namespace {

SequenceRow row(const std::string& trace, const std::string& method, const char* pixels, double ms, double db) {
    SequenceRow r;
    r.scene = "mandelbulb";
    r.trace = trace;
    r.setting.method = method;
    r.setting.pixels = pixels;
    for (int i = 0; i < 3; ++i) {
        SequenceFrame f;
        f.index = i;
        f.gpu_ms = ms;
        f.compared = true;
        f.picture_psnr = db;
        r.frames.push_back(f);
    }
    r.summarize();
    return r;
}

TEST(EqualPicture, the_cheapest_setting_at_naives_picture_is_found_per_trace_and_pixel_set) {
    std::vector<SequenceRow> rows{
        row("walk", "naive", kAllPixels, 40.0, 30.0),
        row("walk", "per-eye", kAllPixels, 30.0, 29.0),            // faster, worse picture
        row("walk", "per-eye + TAA", kAllPixels, 33.0, 32.0),      // the answer
        row("walk", "per-eye + TAAU 1.5", kAllPixels, 36.0, 30.0), // equal picture, slower than TAA
        row("walk", "per-eye + TAAU 2", kAllPixels, 10.0, 31.0),   // would win, but failed
        row("walk", "naive", kMaskedPixels, 20.0, 28.0),
        row("walk", "per-eye", kMaskedPixels, 15.0, 27.0),          // nothing reaches naive here
    };
    rows[4].error = "device lost";
    const auto entries = cheapest_at_naive_picture(rows);
    ASSERT_EQ(entries.size(), 2u);
    ASSERT_NE(entries[0].cheapest, nullptr);
    EXPECT_EQ(entries[0].cheapest->setting.method, "per-eye + TAA");
    EXPECT_EQ(entries[0].best->setting.method, "per-eye + TAA");
    EXPECT_EQ(entries[1].pixels, kMaskedPixels);
    EXPECT_EQ(entries[1].cheapest, nullptr);
    EXPECT_EQ(entries[1].best->setting.method, "naive");
    const std::string md = equal_picture_markdown(entries);
    EXPECT_NE(md.find("| per-eye + TAA: 33.0 ms, 32.0 dB | 1.21 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| none |  |"), std::string::npos) << md;
}

}  // namespace
}  // namespace fg::bench
