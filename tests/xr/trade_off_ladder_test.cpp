// The governor's ladder from `fgplay bench` output: the measured Pareto front, in time order, read
// from the results.json the benchmark's own writer produces; bad files are refused naming the entry.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <fstream>

#include "bench_report.h"
#include "scratch_dir.h"
#include "frame/trade_off_front.h"
#include "frame/trade_off_ladder.h"

namespace fg::xr {
namespace {

namespace fs = std::filesystem;

bench::BenchRow row(const std::string& view, const std::string& setting, double ms, double wrong, FrameSettings f = {}) {
    bench::BenchRow r;
    r.view = view;
    r.setting = setting;
    r.pass_ms["frame"] = ms;
    r.misclassified_pct = wrong;
    f.width = f.height = f.width == 256 ? 128 : f.width;   // 128 per eye unless the setting says otherwise
    r.frame = f;
    r.size = f.width;
    return r;
}

// Two views; "dominated" is slower and less accurate than "per-eye", "tie" as fast as "fovea" but
// worse, "broken" failed in one view.
std::string write_bench(const fs::path& folder) {
    fs::create_directories(folder);
    FrameSettings naive, fovea, eps, half;
    naive.stereo = StereoMode::Naive;
    fovea.foveation = 0.5;
    fovea.lens_mask = true;
    eps.knobs["epsilon"] = 1.0;
    half.width = half.height = 64;
    bench::BenchReport report;
    report.scene = "test";
    report.size = 128;
    for (const char* view : {"afar", "filled"}) {
        report.rows.push_back(row(view, "naive", 100.0, 0.10, naive));
        report.rows.push_back(row(view, "per-eye", 60.0, 0.30));
        report.rows.push_back(row(view, "dominated", 80.0, 0.50, eps));
        report.rows.push_back(row(view, "fovea", 20.0, 1.00, fovea));
        report.rows.push_back(row(view, "tie", 20.0, 1.50, eps));
        report.rows.push_back(row(view, "half size", 10.0, 3.00, half));
        bench::BenchRow broken = row(view, "broken", 1.0, 0.0);
        if (std::string(view) == "filled") broken.error = "out of memory";
        report.rows.push_back(broken);
    }
    report.write(folder.string());
    return (folder / "results.json").string();
}

PackManifest manifest_with_epsilon() {
    PackManifest m;
    m.name = "test";
    ManifestSpecConstant e;
    e.name = "epsilon";
    e.value = 0.5;
    e.min = 0.01;
    e.max = 4.0;
    m.spec_constants.push_back(e);
    return m;
}

// Each test's files in its own temporary folder, removed when the test ends.
class TradeOffs : public ::testing::Test {
protected:
    fs::path scratch(const char* name) const { return dir_ / name; }
    std::string write_text(const char* name, const std::string& text) const {
        fs::path p = scratch(name);
        std::ofstream(p) << text;
        return p.string();
    }

private:
    test::ScratchDir dir_{"fg_trade_offs"};
};

TEST_F(TradeOffs, TheBenchJsonYieldsItsParetoFrontInTimeOrder) {
    auto front = read_trade_offs(write_bench(scratch("front")));
    std::vector<std::string> names;
    for (const auto& t : front) names.push_back(t.setting);
    EXPECT_EQ(names, (std::vector<std::string>{"half size", "fovea", "per-eye", "naive"}));
    for (std::size_t i = 1; i < front.size(); ++i) {
        EXPECT_GT(front[i].time_ms, front[i - 1].time_ms);
        EXPECT_LT(front[i].wrong_pct, front[i - 1].wrong_pct);
    }
    EXPECT_DOUBLE_EQ(front[0].render_scale, 0.5);
    EXPECT_DOUBLE_EQ(front[1].time_ms, 40.0);   // summed over the two views
    EXPECT_DOUBLE_EQ(front[1].frame.foveation, 0.5);
    EXPECT_EQ(front[3].frame.stereo, StereoMode::Naive);
}

TEST_F(TradeOffs, TheBenchWritesTheSameFrontIntoItsJson) {
    std::ifstream in(write_bench(scratch("written")));
    auto j = nlohmann::json::parse(in);
    ASSERT_EQ(j["trade_offs"].size(), 4u);
    EXPECT_EQ(j["trade_offs"][0]["setting"], "half size");
    EXPECT_EQ(j["trade_offs"][3]["setting"], "naive");
}

TEST_F(TradeOffs, TheGovernorNeverChoosesADominatedSetting) {
    auto ladder = trade_off_ladder(manifest_with_epsilon(), read_trade_offs(write_bench(scratch("ladder"))));
    ASSERT_EQ(ladder.size(), 4u);
    EXPECT_EQ(ladder.front().name, "naive");   // most accurate first
    EXPECT_EQ(ladder.back().name, "half size");
    FrameGovernor g(ladder);
    std::vector<std::string> chosen{g.current().name};
    for (int i = 0; i < 200; ++i)
        if (g.observe(50.0, 1.0)) chosen.push_back(g.current().name);
    for (int i = 0; i < 400; ++i)
        if (g.observe(0.1, 1.0)) chosen.push_back(g.current().name);
    EXPECT_EQ(chosen, (std::vector<std::string>{"naive", "per-eye", "fovea", "half size", "fovea", "per-eye", "naive"}));
    EXPECT_NE(g.current().describe().find("\"naive\": naive"), std::string::npos) << g.current().describe();
}

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const TradeOffError& e) {
        return e.what();
    }
    return "no error";
}

TEST_F(TradeOffs, BadFilesAreRefusedNamingTheEntry) {
    std::string good = write_bench(scratch("bad"));
    std::ifstream in(good);
    const auto j = nlohmann::json::parse(in);
    auto with = [&](const char* name, const std::function<void(nlohmann::json&)>& edit) {
        nlohmann::json copy = j;
        edit(copy);
        return write_text(name, copy.dump());
    };
    EXPECT_NE(error_of([&] { read_trade_offs(write_text("notjson", "{\"rows\": [")); }).find("not JSON (byte"), std::string::npos);
    EXPECT_NE(error_of([&] { read_trade_offs("/no/such/bench.json"); }).find("cannot be read"), std::string::npos);
    EXPECT_NE(error_of([&] { read_trade_offs(with("norows", [](auto& x) { x.erase("rows"); })); }).find(":/rows: missing"),
              std::string::npos);
    auto old = error_of([&] { read_trade_offs(with("old", [](auto& x) { x["rows"][0].erase("settings"); })); });
    EXPECT_NE(old.find(":/rows/0/settings: missing: the file was written by an older `fgplay bench`"), std::string::npos) << old;
    auto stereo = error_of([&] { read_trade_offs(with("stereo", [](auto& x) { x["rows"][2]["settings"]["stereo"] = "sideways"; })); });
    EXPECT_NE(stereo.find(":/rows/2/settings/stereo: expected reproject, per-eye or naive"), std::string::npos) << stereo;
    auto time = error_of([&] { read_trade_offs(with("time", [](auto& x) { x["rows"][1]["pass_ms"]["frame"] = 0.0; })); });
    EXPECT_NE(time.find(":/rows/1/pass_ms/frame: no GPU time"), std::string::npos) << time;
    auto scale = error_of([&] { read_trade_offs(with("scale", [](auto& x) { x["rows"][3]["settings"]["render_scale"] = 3; })); });
    EXPECT_NE(scale.find(":/rows/3/settings/render_scale: 3 is outside [0.05, 1]"), std::string::npos) << scale;
    auto other = error_of([&] {
        PackManifest m = manifest_with_epsilon();
        m.spec_constants.clear();
        trade_off_ladder(m, read_trade_offs(good));
    });
    EXPECT_EQ(other, "no error");   // the front holds no epsilon setting: "dominated" and "tie" are off it
    auto range = error_of([&] {
        PackManifest m = manifest_with_epsilon();
        m.spec_constants[0].max = 0.5;
        nlohmann::json copy = j;
        copy["rows"][3]["settings"]["knobs"]["epsilon"] = 1.0;   // "fovea" in the afar view
        copy["rows"][10]["settings"]["knobs"]["epsilon"] = 1.0;  // and in the filled view
        trade_off_ladder(m, read_trade_offs(write_text("range", copy.dump())));
    });
    EXPECT_NE(range.find("setting \"fovea\": epsilon = 1 is outside the knob's range"), std::string::npos) << range;
}

// The committed fixture is real `fgplay bench --quick` output for the gallery Mandelbulb.
TEST_F(TradeOffs, TheCommittedQuickBenchYieldsAFrontThatBeatsEveryOtherSetting) {
    const std::string path = std::string(FG_XR_FIXTURES) + "/mandelbulb_bench_quick.json";
    auto front = read_trade_offs(path);
    ASSERT_GE(front.size(), 2u);
    std::ifstream in(path);
    auto j = nlohmann::json::parse(in);
    std::map<std::string, std::pair<double, double>> all;   // setting -> (time, wrong), over the views
    std::map<std::string, int> views;
    for (const auto& r : j["rows"]) {
        if (!r["error"].get<std::string>().empty()) continue;
        auto& a = all[r["setting"]];
        a.first += r["pass_ms"]["frame"].get<double>();
        a.second += r["wrong_pct"].get<double>();
        ++views[r["setting"]];
    }
    for (auto& [name, a] : all) {
        a.second /= views[name];
        bool on_front = std::any_of(front.begin(), front.end(), [&](const TradeOff& t) { return t.setting == name; });
        bool dominated = std::any_of(front.begin(), front.end(), [&](const TradeOff& t) {
            return t.setting != name && t.time_ms <= a.first && t.wrong_pct <= a.second;
        });
        EXPECT_NE(on_front, dominated) << name << ": on the front exactly when nothing beats it";
    }
}

}  // namespace
}  // namespace fg::xr
