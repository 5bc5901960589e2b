#include "sequence_trade_offs.h"

#include "frame/trade_off_front.h"

namespace fg::bench {

nlohmann::json sequence_trade_offs_json(const SequenceReport& report, const std::string& scene) {
    nlohmann::json j;
    j["scene"] = scene;
    j["device"] = report.device;
    j["size"] = report.size;
    j["source"] = "fgplay bench --sequence: a view is a head trace, pass_ms.frame its median GPU time per frame";
    j["rows"] = nlohmann::json::array();
    for (const auto& r : report.rows) {
        if (r.scene != scene) continue;
        std::string error = r.error;
        if (error.empty() && r.rendered == 0) error = "every frame of the trace was dark";
        j["rows"].push_back({{"view", r.trace},
                             {"setting", r.setting.name()},
                             {"settings", trade_off_settings_json(r.setting.frame, report.size)},
                             {"pass_ms", {{"frame", r.median_ms}}},
                             {"frame_ms_p99", r.p99_ms},
                             {"wrong_pct", optional_number(r.misclassified_mean)},
                             {"picture_psnr_db", r.picture_psnr_median},
                             {"overstepped_pct", optional_number(r.overstepped_mean)},
                             {"error", error}});
    }
    try {
        j["trade_offs"] = trade_off_front_json(j);
    } catch (const TradeOffError& e) {
        j["trade_offs"] = nlohmann::json::array();
        j["front_error"] = e.what();
    }
    return j;
}

}  // namespace fg::bench
