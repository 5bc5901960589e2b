#include "trade_off_front.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>

#include <fmt/format.h>

namespace fg {

TradeOffError::TradeOffError(std::string w, const std::string& what) : std::runtime_error(w + ": " + what), where(std::move(w)) {}

std::vector<TradeOff> pareto_front(std::vector<TradeOff> settings) {
    const bool by_picture =
        std::all_of(settings.begin(), settings.end(), [](const TradeOff& t) { return t.picture_mse >= 0.0; });
    std::stable_sort(settings.begin(), settings.end(), [&](const TradeOff& a, const TradeOff& b) {
        return a.time_ms != b.time_ms ? a.time_ms < b.time_ms : a.error(by_picture) < b.error(by_picture);
    });
    // Walking from the cheapest, a setting earns its place only by being more accurate than every
    // cheaper one: paying more time for no less error is never a step up.
    std::vector<TradeOff> front;
    // Ordered by misclassification, a setting whose depths were not measured has no place.
    if (!by_picture) std::erase_if(settings, [](const TradeOff& t) { return std::isnan(t.wrong_pct); });
    for (auto& s : settings)
        if (front.empty() || s.error(by_picture) < front.back().error(by_picture)) front.push_back(std::move(s));
    return front;
}

nlohmann::json optional_number(double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); }

nlohmann::json trade_off_settings_json(const FrameSettings& f, std::uint32_t bench_size) {
    return {{"stereo", stereo_mode_name(f.stereo)},
            {"cone_levels", f.cone_levels},
            {"lens_mask", f.lens_mask},
            {"foveation", std::max(f.foveation, 0.0)},
            {"render_scale", bench_size ? static_cast<double>(f.shown_width()) / bench_size : 1.0},
            {"taa", f.taa},
            {"taa_upscale", f.taa_upscale()},
            {"knobs", f.knobs}};
}

namespace {

const nlohmann::json& member(const nlohmann::json& j, const std::string& pointer, const char* key) {
    if (!j.is_object()) throw TradeOffError(pointer, "expected an object");
    auto it = j.find(key);
    if (it == j.end()) throw TradeOffError(pointer + "/" + key, "missing");
    return *it;
}

double number(const nlohmann::json& j, const std::string& pointer, double lo, double hi) {
    if (!j.is_number()) throw TradeOffError(pointer, fmt::format("expected a number, found {}", j.dump()));
    double v = j.get<double>();
    if (!std::isfinite(v) || v < lo || v > hi) throw TradeOffError(pointer, fmt::format("{} is outside [{:g}, {:g}]", v, lo, hi));
    return v;
}

}  // namespace

void read_trade_off_settings(const nlohmann::json& j, const std::string& pointer, TradeOff& out) {
    const auto& stereo = member(j, pointer, "stereo");
    if (!stereo.is_string() || !parse_stereo_mode(stereo.get<std::string>(), out.frame.stereo))
        throw TradeOffError(pointer + "/stereo", fmt::format("expected reproject, per-eye or naive, found {}", stereo.dump()));
    out.frame.cone_levels = static_cast<std::uint32_t>(number(member(j, pointer, "cone_levels"), pointer + "/cone_levels", 1, 12));
    const auto& lens = member(j, pointer, "lens_mask");
    if (!lens.is_boolean()) throw TradeOffError(pointer + "/lens_mask", "expected true or false");
    out.frame.lens_mask = lens.get<bool>();
    out.frame.foveation = number(member(j, pointer, "foveation"), pointer + "/foveation", 0.0, 4.0);
    out.render_scale = number(member(j, pointer, "render_scale"), pointer + "/render_scale", 0.05, 1.0);
    // Temporal anti-aliasing: absent in files written before the benchmark measured it.
    if (auto taa = j.find("taa"); taa != j.end()) {
        if (!taa->is_boolean()) throw TradeOffError(pointer + "/taa", "expected true or false");
        out.frame.taa = taa->get<bool>();
    }
    if (auto upscale = j.find("taa_upscale"); upscale != j.end()) {
        out.taa_upscale = number(*upscale, pointer + "/taa_upscale", 1.0, 2.0);
        if (out.taa_upscale > 1.0 && !out.frame.taa)
            throw TradeOffError(pointer + "/taa_upscale", "temporal upsampling without \"taa\": true");
    }
    const auto& knobs = member(j, pointer, "knobs");
    if (!knobs.is_object()) throw TradeOffError(pointer + "/knobs", "expected an object of knob values");
    out.frame.knobs.clear();
    for (const auto& [name, value] : knobs.items())
        out.frame.knobs[name] = number(value, pointer + "/knobs/" + name, -1e9, 1e9);
}

std::vector<TradeOff> trade_offs_from_bench_json(const nlohmann::json& results) {
    const auto& rows = member(results, "", "rows");
    if (!rows.is_array() || rows.empty()) throw TradeOffError("/rows", "expected the benchmark's rows (a non-empty array)");
    struct Sum {
        TradeOff t;
        std::string first;   // pointer of its first row, for messages
        int views = 0;
        bool failed = false;
    };
    std::map<std::string, Sum> sums;
    std::vector<std::string> order, views;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::string at = fmt::format("/rows/{}", i);
        const auto& row = rows[i];
        const auto& name = member(row, at, "setting");
        const auto& view = member(row, at, "view");
        if (!name.is_string() || name.get<std::string>().empty()) throw TradeOffError(at + "/setting", "expected the setting's name");
        if (!view.is_string()) throw TradeOffError(at + "/view", "expected the view's name");
        if (std::find(views.begin(), views.end(), view.get<std::string>()) == views.end()) views.push_back(view);
        auto [it, fresh] = sums.try_emplace(name.get<std::string>());
        Sum& s = it->second;
        if (row.contains("error") && row["error"].is_string() && !row["error"].get<std::string>().empty()) {
            s.failed = true;   // a setting that failed in one view cannot be trusted in any
            if (fresh) order.push_back(name);
            continue;
        }
        if (!row.contains("settings"))
            throw TradeOffError(at + "/settings", "missing: the file was written by an older `fgplay bench`; run it again");
        TradeOff t;
        t.setting = name;
        read_trade_off_settings(row["settings"], at + "/settings", t);
        const auto& pass_ms = member(row, at, "pass_ms");
        double ms = number(member(pass_ms, at + "/pass_ms", "frame"), at + "/pass_ms/frame", 0.0, 1e7);
        if (ms <= 0.0) throw TradeOffError(at + "/pass_ms/frame", "no GPU time (the benchmark's device had no timestamps?)");
        // Null where the benchmark could not compare the depths (temporal upsampling): such a row
        // is judged by its picture alone.
        const auto& wrong_json = member(row, at, "wrong_pct");
        double wrong = wrong_json.is_null() && row.contains("picture_psnr_db")
                           ? std::numeric_limits<double>::quiet_NaN()
                           : number(wrong_json, at + "/wrong_pct", 0.0, 100.0);
        // The picture's PSNR (fgplay bench --sequence) as a mean squared error on a [0, 1] scale.
        double mse = -1.0;
        if (row.contains("picture_psnr_db"))
            mse = std::pow(10.0, -number(row["picture_psnr_db"], at + "/picture_psnr_db", 0.0, 200.0) / 10.0);
        if (fresh) {
            order.push_back(name);
            s.t = t;
            s.first = at;
        } else if (s.views > 0 && (t.frame.stereo != s.t.frame.stereo || t.frame.knobs != s.t.frame.knobs ||
                                   t.frame.foveation != s.t.frame.foveation || t.render_scale != s.t.render_scale ||
                                   t.frame.cone_levels != s.t.frame.cone_levels || t.frame.taa != s.t.frame.taa ||
                                   t.taa_upscale != s.t.taa_upscale)) {
            throw TradeOffError(at + "/settings", fmt::format("setting \"{}\" differs from its row {}", t.setting, s.first));
        } else if (s.views == 0) {
            s.t = t;
            s.first = at;
        }
        s.t.time_ms += ms;
        s.t.wrong_pct += wrong;
        // One view without the picture's error leaves the setting without it.
        s.t.picture_mse = mse < 0.0 || (s.views > 0 && s.t.picture_mse < 0.0) ? -1.0 : (s.views ? s.t.picture_mse : 0.0) + mse;
        ++s.views;
    }
    std::vector<TradeOff> measured;
    for (const auto& name : order) {
        Sum& s = sums[name];
        if (s.failed || s.views != static_cast<int>(views.size())) continue;
        s.t.wrong_pct /= s.views;
        if (s.t.picture_mse >= 0.0) s.t.picture_mse /= s.views;
        measured.push_back(s.t);
    }
    if (measured.empty()) throw TradeOffError("/rows", "no setting was measured without error in every view");
    return pareto_front(std::move(measured));
}

nlohmann::json trade_off_front_json(const nlohmann::json& results) {
    auto front = nlohmann::json::array();
    for (const auto& t : trade_offs_from_bench_json(results)) {
        nlohmann::json entry{{"setting", t.setting}, {"time_ms", t.time_ms}, {"wrong_pct", optional_number(t.wrong_pct)}};
        if (t.picture_mse > 0.0) entry["picture_psnr_db"] = -10.0 * std::log10(t.picture_mse);
        front.push_back(std::move(entry));
    }
    return front;
}

std::vector<TradeOff> read_trade_offs(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw TradeOffError(path, "cannot be read");
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        throw TradeOffError(path, fmt::format("not JSON (byte {}): {}", e.byte, e.what()));
    }
    try {
        return trade_offs_from_bench_json(j);
    } catch (const TradeOffError& e) {
        throw TradeOffError(path + ":" + (e.where.empty() ? "/" : e.where), std::string(e.what()).substr(e.where.size() + 2));
    }
}

}  // namespace fg
