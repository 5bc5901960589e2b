#include "bench_settings.h"

#include <cmath>

#include <fmt/format.h>

namespace fg::bench {

namespace {

std::string number(double v) { return fmt::format("{:g}", v); }

// What each marched light term costs (a node's steps or rays knob: soft shadow, marched AO): the
// frame with the term off (0) and at half its work, beside the default. Their group tells the
// summary that they change the look, which the misclassified pixels do not see.
template <class Add>
void light_term_knobs(const FrameSettings& def, const PackManifest& m, Add add) {
    for (const auto& s : m.spec_constants)
        if (s.name.starts_with("steps.") || s.name.starts_with("rays."))
            for (double v : {0.0, std::floor(s.value / 2.0)}) {
                FrameSettings f = def;
                f.knobs[s.name] = v;
                add(kLightTermGroup, fmt::format("{}={}", s.name, number(v)), f);
            }
}

}  // namespace

std::vector<BenchSetting> make_sweep(const PackManifest& m, const SweepOptions& o) {
    FrameSettings def;
    def.width = def.height = o.size;
    def.stereo = StereoMode::PerEye;
    def.cone_levels = 5;
    def.foveation = 0.0;
    std::vector<BenchSetting> out;
    auto add = [&](std::string group, std::string name, FrameSettings f) {
        out.push_back({std::move(name), std::move(group), std::move(f), false});
    };

    FrameSettings naive = def;
    naive.stereo = StereoMode::Naive;
    out.push_back({"naive per-eye sphere tracing", "baseline", naive, true});
    add("default", "per-eye conemarch (default)", def);

    auto knob = [&](const std::string& k, std::vector<double> values) {
        for (double v : values) {
            FrameSettings f = def;
            f.knobs[k] = v;
            add(k, fmt::format("{}={}", k, number(v)), f);
        }
    };
    auto mode = [&](const std::string& name, StereoMode s, std::map<std::string, double> knobs = {}) {
        FrameSettings f = def;
        f.stereo = s;
        f.knobs = std::move(knobs);
        add("stereo", name, f);
    };

    // Fewer pixels: the lens mask, fixed foveation, and both.
    auto pixels = [&](bool lens, double fovea, std::map<std::string, double> knobs = {}) {
        FrameSettings f = def;
        f.lens_mask = lens;
        f.foveation = fovea;
        f.knobs = std::move(knobs);
        std::string name = lens ? "lens mask" : "";
        if (fovea > 0.0) name += fmt::format("{}foveation {}", lens ? " + " : "", number(fovea));
        for (const auto& [k, v] : f.knobs) name += fmt::format(" {}={}", k, number(v));
        add("pixels", name, f);
    };

    if (o.quick) {
        light_term_knobs(def, m, add);
        pixels(true, 0.0);
        pixels(false, 0.5);
        knob("epsilon", {1.0});
        knob("fine_steps", {16});
        knob("overrelax", {1.4});
        knob("persistent_lanes", {1});
        mode("reproject", StereoMode::Reproject);
        mode("reproject, trusting depth", StereoMode::Reproject, {{"reproject_trust_depth", 1}});
        return out;
    }

    knob("epsilon", {0.25, 1.0, 2.0});
    knob("fine_steps", {16, 32, 128});
    knob("max_steps", {64});
    for (const auto& f : m.fractals) {
        if (const auto* it = m.find_spec(f.iterations_spec)) {
            double base = it->value;
            knob(it->name, {std::max(1.0, base - 2), base + 2, base + 4});
        }
        if (const auto* b = m.find_spec(f.bias_spec)) knob(b->name, {0.0, 1.05, 1.2});
    }
    light_term_knobs(def, m, add);
    knob("step_scale", {0.8, 1.2});
    for (std::uint32_t levels : {1u, 3u, 7u}) {
        FrameSettings f = def;
        f.cone_levels = levels;
        add("cone_levels", fmt::format("cone_levels={}", levels), f);
    }
    knob("cone_steps", {16});
    knob("cone_stop", {1.1, 3.0});
    knob("overrelax", {1.2, 1.5});
    knob("tail_after", {8, 16});
    knob("persistent_lanes", {1});
    // How full a subgroup stays before its idle lanes refill: a GPU's lever (32 or 64 lanes).
    for (double burst : {0.5, 0.75, 1.0}) {
        FrameSettings f = def;
        f.knobs = {{"persistent_lanes", 1}, {"lane_burst", burst}};
        add("lane_burst", fmt::format("persistent_lanes=1 lane_burst={}", number(burst)), f);
    }
    {
        // The second baseline: naive sphere tracing with persistent lanes.
        FrameSettings f = naive;
        f.knobs["persistent_lanes"] = 1;
        add("persistent_lanes", "naive, persistent_lanes=1", f);
    }
    knob("normal_taps", {6});
    knob("shade_reuse", {1.0, 4.0});
    pixels(true, 0.0);
    for (double fovea : {0.35, 0.5, 0.7}) pixels(false, fovea);
    pixels(true, 0.5);
    pixels(true, 0.5, {{"epsilon", 1.0}, {"overrelax", 1.3}});
    mode("reproject", StereoMode::Reproject);
    mode("reproject, trusting depth", StereoMode::Reproject, {{"reproject_trust_depth", 1}});
    mode("reproject, 8 fix-up steps", StereoMode::Reproject, {{"reproject_fixup_steps", 8}});
    for (std::uint32_t size : {o.size / 2}) {
        FrameSettings f = def;
        f.width = f.height = size;
        // The output stays o.size: its pixels set the hit threshold, as the governor's lower scales do.
        f.detail_scale = static_cast<double>(size) / o.size;
        add("resolution", fmt::format("{}x{} per eye", size, size), f);
    }

    // Jointly: the knobs that matter most, on a grid.
    for (double eps : {0.5, 1.0})
        for (double steps : {32.0, 64.0})
            for (double omega : {1.0, 1.3})
                for (int trust : {0, 1}) {
                    FrameSettings f = def;
                    f.knobs = {{"epsilon", eps}, {"fine_steps", steps}, {"overrelax", omega}};
                    if (trust) {
                        f.stereo = StereoMode::Reproject;
                        f.knobs["reproject_trust_depth"] = 1;
                    }
                    add("grid", fmt::format("{} eps={} fine={} omega={}", trust ? "reproject-trust" : "per-eye",
                                            number(eps), number(steps), number(omega)),
                        f);
                }
    return out;
}

}  // namespace fg::bench
