#pragma once
// The accuracy-versus-time trade-off that `fgplay bench` measures, as settings a player can switch
// between. A setting's cost is its GPU time summed over the benchmark's views, its error the
// misclassified pixels averaged over them, or the picture's error against its ground truth where
// the benchmark measured it (fgplay bench --sequence); the Pareto front keeps the settings that no
// other one beats on both. The benchmark writes the front into results.json; the frame governor walks it.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "frame_settings.h"

namespace fg {

struct TradeOff {
    std::string setting;       // the benchmark's name for it: "foveation 0.5"
    FrameSettings frame;       // width and height are not used: see render_scale
    double taa_upscale = 1.0;       // temporal upsampling's factor (frame.taa), 1 without
    double render_scale = 1.0; // of the per-eye size the benchmark measured at
    double time_ms = 0.0;      // GPU time per stereo frame, summed over the views
    double wrong_pct = 0.0;    // misclassified pixels, mean over the views
    // The picture's error against its ground truth (rows' picture_psnr_db): mean squared error on a
    // [0, 1] scale over the views; < 0 where a row did not measure it.
    double picture_mse = -1.0;
    // The error the front compares: the picture's where every setting measured it (then a cleaner
    // picture, anti-aliasing included, counts), else the misclassified pixels.
    double error(bool by_picture) const { return by_picture ? picture_mse : wrong_pct; }
};

// A bad trade-off file: `where` is the JSON pointer of the entry at fault ("/rows/3/settings/stereo").
struct TradeOffError : std::runtime_error {
    TradeOffError(std::string where, const std::string& what);
    std::string where;
};

// Cheapest first. A setting that another one matches or beats on both time and error is not on it.
std::vector<TradeOff> pareto_front(std::vector<TradeOff> settings);

// A measure as JSON: null where it was not measured (NaN).
nlohmann::json optional_number(double v);

// How a setting is written into results.json ("settings" of each row), and read back. `bench_size`
// is the per-eye size the benchmark ran at, so a resolution setting becomes a render scale.
nlohmann::json trade_off_settings_json(const FrameSettings& f, std::uint32_t bench_size);
void read_trade_off_settings(const nlohmann::json& j, const std::string& pointer, TradeOff& out);

// The front of a results.json from `fgplay bench`: only settings measured without error in every
// view count. Throws TradeOffError naming the file's bad entry.
std::vector<TradeOff> trade_offs_from_bench_json(const nlohmann::json& results);
// The same front as results.json's "trade_offs": setting, time_ms, wrong_pct, cheapest first.
nlohmann::json trade_off_front_json(const nlohmann::json& results);
std::vector<TradeOff> read_trade_offs(const std::string& path);

}  // namespace fg
