#include "sequence_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <numeric>
#include <set>
#include <tuple>

#include "equal_picture.h"
#include "frame_measures.h"
#include "head_trace.h"
#include "plot_script.h"
#include "sequence_trade_offs.h"

namespace fg::bench {

namespace {

double mean(const std::vector<double>& v) {
    return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

double largest(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }
double smallest(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

// A blank cell where a figure is missing (a baseline that failed, lanes not counted yet).
std::string ratio_cell(double x) { return x > 0.0 ? fmt::format("{:.3f}", x) : std::string(); }

std::string lane_cell(const SequenceRow& r, const std::string& group) {
    auto it = r.lanes.find(group);
    return it == r.lanes.end() || it->second.total == 0 ? std::string()
                                                        : fmt::format("{:.3f}", it->second.efficiency());
}

// "march.L4 62 %, tail 40 %" for the Markdown table; blank while lanes are not counted.
std::string lanes_summary(const SequenceRow& r) {
    std::string out;
    for (const auto& g : r.counter_groups)
        if (auto cell = lane_cell(r, g); !cell.empty())
            out += fmt::format("{}{} {:.0f} %", out.empty() ? "" : ", ", g, 100.0 * r.lanes.at(g).efficiency());
    return out;
}

std::string csv_text(std::string s) {
    std::replace(s.begin(), s.end(), '"', '\'');
    return "\"" + s + "\"";
}

}  // namespace

void SequenceRow::summarize() {
    std::vector<double> ms, wrong, over, over_march, quality, evals, iterations, picture, flickers;
    rendered = dark = counted = 0;
    not_finite_worst = 0;
    std::vector<double> after;
    for (const auto& f : frames) {
        if (f.dark) {
            ++dark;
            continue;
        }
        ++rendered;
        ms.push_back(f.gpu_ms);
        if (f.gpu_ms > 0.0) after.push_back(f.after_march_ms / f.gpu_ms);
        if (f.depths_compared) {
            wrong.push_back(f.misclassified_pct);
            over.push_back(f.overstepped_pct);
            over_march.push_back(f.overstepped_march_pct);
        }
        if (f.compared) {
            quality.push_back(f.psnr);
            picture.push_back(f.picture_psnr);
            if (f.flicker >= 0.0) flickers.push_back(f.flicker);
            not_finite_worst = std::max(not_finite_worst, f.not_finite);
        }
        if (f.evaluations_per_pixel >= 0.0) {
            ++counted;
            evals.push_back(f.evaluations_per_pixel);
            iterations.push_back(f.iterations_per_pixel);
        }
    }
    median_ms = median(ms);
    after_march_share = median(after);
    p99_ms = percentile(ms, 99.0);
    worst_ms = largest(ms);
    evaluations_per_pixel = mean(evals);
    iterations_per_pixel = mean(iterations);
    reuse_skipped_fraction = reuse_skipped_frames > 0 ? reuse_skipped_sum / reuse_skipped_frames : 0.0;
    const double none = wrong.empty() && !quality.empty() ? std::numeric_limits<double>::quiet_NaN() : 0.0;
    misclassified_mean = wrong.empty() ? none : mean(wrong);
    misclassified_worst = wrong.empty() ? none : largest(wrong);
    overstepped_mean = wrong.empty() ? none : mean(over);
    overstepped_worst = wrong.empty() ? none : largest(over);
    overstepped_march_mean = wrong.empty() ? none : mean(over_march);
    overstepped_march_worst = wrong.empty() ? none : largest(over_march);
    psnr_mean = mean(quality);
    psnr_worst = smallest(quality);
    picture_psnr_median = median(picture);
    picture_psnr_worst = smallest(picture);
    flicker_median = median(flickers);
    flicker_worst = largest(flickers);
}

std::string SequenceRow::brief() const {
    return fmt::format(
        "{:8.2f} ms (p99 {:.2f}, worst {:.2f})  {:6.2f} evals/px  {:.3f}% wrong (worst {:.3f})  "
        "picture {:.1f} dB (worst {:.1f}), flicker {:.2f}",
        median_ms, p99_ms, worst_ms, evaluations_per_pixel, misclassified_mean, misclassified_worst, picture_psnr_median,
        picture_psnr_worst, flicker_median);
}

void SequenceReport::fill_speedups() {
    using Key = std::tuple<std::string, std::string, std::string>;   // scene, trace, pixels
    std::map<Key, const SequenceRow*> naive, naive_lanes;
    for (const auto& r : rows) {
        if (!r.error.empty() || r.median_ms <= 0.0) continue;
        Key key{r.scene, r.trace, r.setting.pixels};
        if (r.setting.baseline == SequenceBaseline::Naive) naive[key] = &r;
        if (r.setting.baseline == SequenceBaseline::NaivePersistent) naive_lanes[key] = &r;
    }
    auto speedups = [](const SequenceRow* base, const SequenceRow& r, double& median_x, double& p99_x) {
        if (!base || !r.error.empty() || r.median_ms <= 0.0 || r.p99_ms <= 0.0) return;
        median_x = base->median_ms / r.median_ms;
        p99_x = base->p99_ms / r.p99_ms;
    };
    for (auto& r : rows) {
        Key key{r.scene, r.trace, r.setting.pixels};
        auto find = [&](const std::map<Key, const SequenceRow*>& m) {
            auto it = m.find(key);
            return it == m.end() ? nullptr : it->second;
        };
        speedups(find(naive), r, r.speedup_median_naive, r.speedup_p99_naive);
        speedups(find(naive_lanes), r, r.speedup_median_naive_lanes, r.speedup_p99_naive_lanes);
    }
}

void SequenceReport::write(const std::string& folder) const {
    namespace fs = std::filesystem;
    std::set<std::string> groups;
    for (const auto& r : rows) groups.insert(r.counter_groups.begin(), r.counter_groups.end());

    std::ofstream csv(fs::path(folder) / "sequence.csv");
    csv << "scene,trace,setting,method,pixels,stereo,persistent_lanes,lens_mask,foveation,size,frames,dark_frames,"
           "counted_frames,frame_ms_median,frame_ms_p99,frame_ms_worst,after_march_share,evals_per_px,iterations_per_px";
    for (const auto& g : groups) csv << ",lanes_" << g;
    csv << ",misclassified_pct_mean,misclassified_pct_worst,overstepped_pct_mean,overstepped_pct_worst,"
           "overstepped_march_pct_mean,overstepped_march_pct_worst,not_finite_worst,"
           "psnr_db_mean,psnr_db_worst,reuse_skipped_fraction,speedup_median_vs_naive,speedup_p99_vs_naive,"
           "speedup_median_vs_naive_lanes,speedup_p99_vs_naive_lanes,picture_psnr_db_median,picture_psnr_db_worst,"
           "flicker_median,flicker_worst,error\n";
    for (const auto& r : rows) {
        const FrameSettings& f = r.setting.frame;
        auto lanes = f.knobs.find("persistent_lanes");
        csv << fmt::format("{},{},{},{},{},{},{},{},{:g},{},{},{},{},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f}", r.scene, r.trace,
                           r.setting.name(), r.setting.method, r.setting.pixels, stereo_mode_name(f.stereo),
                           lanes != f.knobs.end() && lanes->second != 0.0 ? 1 : 0, f.lens_mask ? 1 : 0,
                           std::max(0.0, f.foveation), f.shown_width(), r.rendered, r.dark, r.counted, r.median_ms, r.p99_ms,
                           r.worst_ms, r.after_march_share, r.evaluations_per_pixel, r.iterations_per_pixel);
        for (const auto& g : groups) csv << "," << lane_cell(r, g);
        // Empty where the depths were not compared (temporal upsampling).
        auto percent = [](double v) { return std::isnan(v) ? std::string() : fmt::format("{:.4f}", v); };
        csv << fmt::format(",{},{},{},{},{},{},{},{:.2f},{:.2f},{:.3f},{},{},{},{},{:.2f},{:.2f},{:.3f},{:.3f},{}\n",
                           percent(r.misclassified_mean), percent(r.misclassified_worst), percent(r.overstepped_mean),
                           percent(r.overstepped_worst), percent(r.overstepped_march_mean),
                           percent(r.overstepped_march_worst), r.not_finite_worst, r.psnr_mean, r.psnr_worst, r.reuse_skipped_fraction,
                           ratio_cell(r.speedup_median_naive), ratio_cell(r.speedup_p99_naive),
                           ratio_cell(r.speedup_median_naive_lanes), ratio_cell(r.speedup_p99_naive_lanes),
                           r.picture_psnr_median, r.picture_psnr_worst, r.flicker_median, r.flicker_worst,
                           r.error.empty() ? "" : csv_text(r.error));
    }

    std::ofstream frames_csv(fs::path(folder) / "sequence_frames.csv");
    frames_csv << "scene,trace,setting,frame,dark,frame_ms,evals_per_px,misclassified_pct,overstepped_pct,"
                  "overstepped_march_pct,psnr_db,picture_psnr_db,flicker,sm_clock_mhz\n";
    for (const auto& r : rows)
        for (const auto& f : r.frames)
            frames_csv << fmt::format(
                "{},{},{},{},{},{:.3f},{},{},{},{}\n", r.scene, r.trace, r.setting.name(), f.index, f.dark ? 1 : 0, f.gpu_ms,
                f.evaluations_per_pixel >= 0.0 ? fmt::format("{:.3f}", f.evaluations_per_pixel) : "",
                f.compared ? (f.depths_compared ? fmt::format("{:.4f},{:.4f},{:.4f}", f.misclassified_pct, f.overstepped_pct,
                                                              f.overstepped_march_pct)
                                                : std::string(",,")) +
                                 fmt::format(",{:.2f},{:.2f}", f.psnr, f.picture_psnr)
                           : std::string(",,,,"),
                f.flicker >= 0.0 ? fmt::format("{:.3f}", f.flicker) : "",
                f.sm_clock_mhz >= 0.0 ? fmt::format("{:.0f}", f.sm_clock_mhz) : "");

    // Per scene, what the frame governor walks: `fgplay xr --trade-offs trade_offs_<scene>.json`.
    std::vector<std::pair<std::string, nlohmann::json>> fronts;
    for (const auto& r : rows)
        if (std::none_of(fronts.begin(), fronts.end(), [&](const auto& f) { return f.first == r.scene; }))
            fronts.emplace_back(r.scene, sequence_trade_offs_json(*this, r.scene));
    for (const auto& [scene, j] : fronts)
        std::ofstream(fs::path(folder) / fmt::format("trade_offs_{}.json", scene)) << j.dump(1);

    std::ofstream md(fs::path(folder) / "sequence.md");
    md << fmt::format(
        "# Head traces at {:g} Hz\n\nDevice: {}. {}x{} per eye, stereo pairs, {} frames per trace. GPU time "
        "per frame from timestamp queries, each renderer warmed up with one untimed frame before each "
        "trace, the settings taking turns frame by frame; median, 99th percentile and worst over the frames "
        "rendered. Evaluations per pixel and "
        "SIMD lanes busy come from a separate counting renderer every {} frames (counting costs "
        "atomics, so it is never the timed one). Errors are against the strict reference of {} "
        "(naive, a tenth of the hit threshold, half steps, 4000 steps), mean and worst frame. The picture's "
        "errors are against its ground truth, 16 jittered samples per pixel of naive tracing at the output "
        "detail: PSNR, and flicker, the frame-to-frame change the ground truth does not have (mean over pixels "
        "and channels, 8-bit levels), median and worst frame. Speed-ups (×) are the baseline's time "
        "over the setting's, same scene, trace and pixel set, same run.\n\n",
        kHeadsetHz, device, size, size, frames, count_every,
        compare_every > 1 ? fmt::format("one frame in {} (`--compare-every {}`)", compare_every, compare_every)
                          : std::string("every frame"));
    if (back_to_back)
        md << "On this GPU a trace's timed frames ran back to back with nothing read back, so its driver saw a "
              "busy GPU and kept its clock; the errors and counts come after, from each setting's counting "
              "renderer rendering the same frames again in order (bit-identical frames).\n\n";
    std::vector<double> clocks;
    for (const auto& r : rows)
        for (const auto& f : r.frames)
            if (f.sm_clock_mhz >= 0.0) clocks.push_back(f.sm_clock_mhz);
    md << shader_clock_paragraph(clocks, max_sm_mhz, "each timed frame");
    if (load_start >= 0.0)
        md << fmt::format(
            "The run took {:.1f} min; the machine's 1-minute load average was {:.1f} at its start and "
            "{:.1f} at its end.\n\n",
            wall_s / 60.0, load_start, load_end);
    md << "| trace | motion |\n|---|---|\n";
    for (const auto& [name, motion] : traces) md << fmt::format("| {} | {} |\n", name, motion);
    md << equal_picture_markdown(cheapest_at_naive_picture(rows));
    md << "\n## Per-eye conemarch against naive\n\nSpeed-up in GPU time per frame (×): on all pixels; with the "
       << kMaskedPixels
       << " against naive with the same; and the same again against naive on all pixels (what the "
          "mask and foveation buy on top).\n\n| scene | trace | median × | p99 × | masked: median × | "
          "masked: p99 × | masked vs all-pixel naive: median × | p99 × |\n"
          "|---|---|---:|---:|---:|---:|---:|---:|\n";
    auto find = [&](const std::string& scene, const std::string& trace, const char* method,
                    const char* pixels) -> const SequenceRow* {
        for (const auto& r : rows)
            if (r.scene == scene && r.trace == trace && r.setting.method == method && r.setting.pixels == pixels &&
                r.error.empty())
                return &r;
        return nullptr;
    };
    std::vector<std::pair<std::string, std::string>> scene_traces;
    for (const auto& r : rows)
        if (std::find(scene_traces.begin(), scene_traces.end(), std::pair{r.scene, r.trace}) == scene_traces.end())
            scene_traces.emplace_back(r.scene, r.trace);
    for (const auto& [scene, trace] : scene_traces) {
        const SequenceRow* all = find(scene, trace, "per-eye", kAllPixels);
        const SequenceRow* masked = find(scene, trace, "per-eye", kMaskedPixels);
        const SequenceRow* naive = find(scene, trace, "naive", kAllPixels);
        auto over = [](const SequenceRow* base, const SequenceRow* r, double SequenceRow::*ms) {
            return base && r && r->*ms > 0.0 ? ratio_cell(base->*ms / r->*ms) : std::string();
        };
        md << fmt::format(
            "| {} | {} | {} | {} | {} | {} | {} | {} |\n", scene, trace,
            all ? ratio_cell(all->speedup_median_naive) : "", all ? ratio_cell(all->speedup_p99_naive) : "",
            masked ? ratio_cell(masked->speedup_median_naive) : "", masked ? ratio_cell(masked->speedup_p99_naive) : "",
            over(naive, masked, &SequenceRow::median_ms), over(naive, masked, &SequenceRow::p99_ms));
    }
    md << "\n## The frame governor's ladder\n\nThe Pareto front of each scene's settings over its traces (median "
          "GPU time per frame summed over the traces against the picture's error), most accurate first: what "
          "`fgplay xr --trade-offs trade_offs_<scene>.json` walks.\n";
    for (const auto& [scene, j] : fronts) {
        md << fmt::format("\n- {}:", scene);
        if (j["trade_offs"].empty()) md << " none (" << j.value("front_error", std::string()) << ")";
        for (auto it = j["trade_offs"].rbegin(); it != j["trade_offs"].rend(); ++it) {
            const auto& e = *it;
            std::string measures = fmt::format("{:.1f} ms", e["time_ms"].get<double>());
            if (e.contains("picture_psnr_db")) measures += fmt::format(", picture {:.1f} dB", e["picture_psnr_db"].get<double>());
            if (e["wrong_pct"].is_number()) measures += fmt::format(", {:.3f} % misclassified", e["wrong_pct"].get<double>());
            md << fmt::format(" {}{} ({})", it == j["trade_offs"].rbegin() ? "" : "→ ", e["setting"].get<std::string>(), measures);
        }
    }
    md << "\n";
    std::string scene_now;
    for (const auto& [scene, trace] : scene_traces) {
        if (scene != scene_now) md << "\n## " << (scene_now = scene) << "\n";
        md << "\n### " << trace
           << "\n\n| setting | frames | median ms | p99 ms | worst ms | after the march | evals/px | fractal iterations/px | SIMD lanes busy | "
              "wrong % mean | wrong % worst | overstep % mean | overstep % worst | PSNR mean | PSNR worst | picture PSNR "
              "median | picture PSNR worst | flicker median | flicker worst | reuse "
              "skipped | × naive (median / p99) | × naive + lanes (median / p99) |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const auto& r : rows) {
            if (r.scene != scene || r.trace != trace) continue;
            bool base = r.setting.baseline != SequenceBaseline::None;
            std::string name = base ? "**" + r.setting.name() + "**" : r.setting.name();
            if (!r.error.empty()) {
                md << fmt::format("| {} | error: {} |||||||||||||||||||||\n", name, r.error);
                continue;
            }
            md << fmt::format(
                "| {} | {}{} | {:.2f} | {:.2f} | {:.2f} | {:.0f} % | {:.2f} | {:.2f} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | "
                "{:.1f} | {:.1f} | {:.1f} | {:.1f} | {:.2f} | {:.2f} | {:.2f} | {} / {} | {} / {} |\n",
                name, r.rendered, r.dark ? fmt::format(" (+{} dark)", r.dark) : "", r.median_ms, r.p99_ms, r.worst_ms,
                100.0 * r.after_march_share, r.evaluations_per_pixel, r.iterations_per_pixel, lanes_summary(r), r.misclassified_mean, r.misclassified_worst,
                r.overstepped_mean, r.overstepped_worst, r.psnr_mean, r.psnr_worst, r.picture_psnr_median,
                r.picture_psnr_worst, r.flicker_median, r.flicker_worst, r.reuse_skipped_fraction,
                ratio_cell(r.speedup_median_naive), ratio_cell(r.speedup_p99_naive),
                ratio_cell(r.speedup_median_naive_lanes), ratio_cell(r.speedup_p99_naive_lanes));
        }
    }
}

void SequenceReport::plot(const std::string& folder) const {
    if (!run_plot_script("plot_sequence.py", folder))
        fmt::print("note: plotting failed (it needs python3-matplotlib); sequence.csv and sequence_frames.csv hold "
                   "every figure\n");
}

std::string SequenceReport::headline() const {
    std::string out;
    for (const auto& r : rows) {
        if (r.setting.method != "per-eye" || !r.error.empty()) continue;
        out += fmt::format("{} {} ({}): per-eye conemarch {:.2f}x naive at the median, {:.2f}x at p99\n", r.scene,
                           r.trace, r.setting.pixels, r.speedup_median_naive, r.speedup_p99_naive);
    }
    return out;
}

}  // namespace fg::bench
