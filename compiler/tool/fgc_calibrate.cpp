// fgc calibrate: measure the conservative-derivative bias a graph's fractals need by bubble
// search on the CPU twin, and write the smallest safe bias into the graph.
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <string>

#include "analysis/bubble_search.h"
#include "analysis/lipschitz_bound.h"
#include "compiler.h"
#include "fgc_commands.h"
#include "graph/graph_text_writer.h"
#include "graph/node_library.h"

namespace fg {
std::span<const EmbeddedFile> embedded_node_files();
}

namespace fg::fgc {

namespace {

void progress_bar(std::size_t done, std::size_t total) {
    constexpr int kWidth = 32;
    int filled = total ? static_cast<int>(kWidth * done / total) : kWidth;
    fmt::print(stderr, "\rbubble search [{}{}] {:3d}% {}/{} samples", std::string(static_cast<std::size_t>(filled), '#'),
               std::string(static_cast<std::size_t>(kWidth - filled), '.'), total ? 100 * done / total : 100, done, total);
    if (done == total) fmt::print(stderr, "\n");
}

// The biases the table shows, within the knob's range.
std::vector<double> bias_grid(double max_bias) {
    std::vector<double> out;
    for (double b : {0.0, 0.5, 0.75, 0.9, 1.0, 1.05, 1.1, 1.25, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0})
        if (b <= max_bias + 1e-12) out.push_back(b);
    return out;
}

// A surface growth figure; infinite where the guarded estimate reaches zero outside the surface.
std::string growth_text(double g) { return std::isfinite(g) ? fmt::format("{:.2f}x", g) : std::string("unbounded"); }

double knob_max(const IrGraph& ir, const std::string& knob) {
    int idx = ir.find(knob.substr(knob.find('.') + 1));
    const auto& n = ir.nodes[static_cast<std::size_t>(idx)];
    for (const auto& port : n.def->inputs)
        if (port.knob == "bias" && port.max) return *port.max;
    return 4.0;
}

}  // namespace

int calibrate(const Common& c, const std::string& graph, const CalibrateOptions& o) {
    Diagnostics diag;
    NodeLibrary lib = NodeLibrary::from_files(embedded_node_files(), diag);
    for (const auto& folder : c.node_folders) lib.load_folder(folder, diag);
    auto fail = [&] {
        fmt::print(stderr, "{}", diag.format(graph));
        return 1;
    };
    std::ifstream in(graph, std::ios::binary);
    if (!in) {
        fmt::print(stderr, "{}: cannot open\n", graph);
        return 1;
    }
    std::stringstream text;
    text << in.rdbuf();
    auto ir = load_and_lower(text.str(), lib, diag);
    if (!ir) return fail();
    auto knobs = BubbleSearch::bias_knobs(*ir);
    if (knobs.empty()) {
        fmt::print("{}: no fractal with a running derivative and a literal bias: nothing to calibrate\n", graph);
        return 0;
    }
    auto ev = CpuEvaluator::create(*ir, diag);
    if (!ev) return fail();
    // The search judges the steps the march would take without a calibrated factor: 1 / L.
    double step_scale = 1.0 / analyse_lipschitz(*ir, diag).bound;
    double max_bias = 1e9;
    for (const auto& k : knobs) max_bias = std::min(max_bias, knob_max(*ir, k));

    BubbleSearchSettings s;
    s.samples = o.samples;
    s.seed = o.seed;
    s.threads = o.threads;
    s.reach_bias = 0.0;
    s.reach_step = step_scale;
    BubbleSearch search(*ev, s);
    auto start = std::chrono::steady_clock::now();
    search.run(o.quiet ? std::function<void(std::size_t, std::size_t)>{} : progress_bar);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // The summary: overshoot rate for each bias (rows) and step multiplier (columns).
    const std::vector<double> steps{1.0, 0.9, 0.8, 0.7, 0.5};
    fmt::print("{}: {} exterior samples (seed {}), {} CPU evaluations in {:.1f} s; step scale 1/L = {:.4g}; bias knobs: {}\n",
               graph, s.samples - static_cast<int>(search.rejected_interior()), s.seed, search.evaluations(), seconds,
               step_scale, fmt::join(knobs, ", "));
    fmt::print("overshoot rate (samples whose step reaches an interior point), by bias and step multiplier:\n");
    fmt::print("  {:>6} |", "bias");
    for (double m : steps) fmt::print(" {:>13}", fmt::format("step x{:.2g}", m));
    fmt::print(" | worst step at x1             | surface growth (median, p90)\n  -------+{}-+------------------------------+-----------------------------\n",
               std::string(steps.size() * 14, '-'));
    for (double b : bias_grid(max_bias)) {
        fmt::print("  {:>6.3g} |", b);
        for (double m : steps) {
            OvershootCount k = search.count(b, step_scale * m);
            fmt::print(" {:>13}", fmt::format("{:.2f}% ({})", 100.0 * k.rate(), k.overshoots));
        }
        OvershootCount full = search.count(b, step_scale);
        SurfaceGrowth g = search.surface_growth(b);
        fmt::print(" | {:<28} | {}, {}\n", full.overshoots ? fmt::format("{:.3f}x the free distance", full.worst) : std::string("-"),
                   growth_text(g.median), growth_text(g.p90));
    }
    // The bias may not move the visible surface more than the growth budget: a bias that removes
    // the last rare overshoot can shrink the estimate a hundredfold near the surface and melt the
    // detail into a blob (the gallery's Julia pool did at the zero-overshoot bias 3.96).
    const double cap = o.max_growth > 0.0 ? search.largest_bias_within_growth(o.max_growth, 0.0, max_bias) : max_bias;
    // The smallest bias within the budget that removes every overshoot at full steps; where none
    // does, the largest step factor at which one does (shorter steps slow every ray, so they come last).
    double factor = 1.0;
    std::optional<double> safe;
    for (double f : {1.0, 0.95, 0.9, 0.85, 0.8, 0.75, 0.7, 0.65, 0.6, 0.55, 0.5}) {
        safe = search.smallest_safe_bias(step_scale * f, 0.0, cap);
        if (safe) {
            factor = f;
            break;
        }
    }
    std::size_t residual = 0;
    if (!safe) {
        // No setting within the budget removes every overshoot: keep full steps (halving them costs
        // twice the march for a fraction of the rare overshoots) and take the smallest bias that
        // leaves the fewest; say so, and what removing them all would cost in growth.
        std::size_t best = SIZE_MAX;
        for (double b = 0.0; b <= cap + 1e-9; b = std::min(b + 0.25, b < cap ? cap : b + 1.0)) {
            std::size_t n = search.count(b, step_scale).overshoots;
            if (n < best) {
                best = n;
                safe = b;
            }
        }
        residual = best;
        OvershootCount k = search.count(*safe, step_scale);
        fmt::print(stderr, "{}: warning: no bias within the surface growth budget ({}x) removes every overshoot; the fewest "
                           "remain at bias {:.2f}: {} of {} samples, worst step {:.2f}x the free distance",
                   graph, o.max_growth, *safe, k.overshoots, k.samples, k.worst);
        for (double f : {1.0, 0.9, 0.8, 0.7, 0.6, 0.5})
            if (auto strict = search.smallest_safe_bias(step_scale * f, 0.0, max_bias)) {
                fmt::print(stderr, " (bias {:.2f} at step factor {:.2f} removes them all but grows the surface {}: "
                                   "--max-growth 0 takes it)",
                           *strict, f, growth_text(search.surface_growth(*strict).p90));
                break;
            }
        fmt::print(stderr, "\n");
    }
    const std::size_t exterior = search.samples().size() - search.rejected_interior();
    OvershootCount off = search.count(0.0, step_scale);
    fmt::print("{} in {} samples: {:.2f} at step factor {:.2f}, surface growth {} (bias 0, full steps: {} overshoots, "
               "{:.2f}%, worst step {:.2f}x the free distance)\n",
               residual ? fmt::format("bias with the fewest overshoots ({})", residual) : std::string("smallest bias without overshoot"),
               exterior, *safe, factor, growth_text(search.surface_growth(*safe).p90), off.overshoots, 100.0 * off.rate(), off.worst);
    if (o.dry_run) return 0;

    auto doc = nlohmann::ordered_json::parse(text.str());
    double value = std::round(*safe * 100.0) / 100.0;
    std::vector<std::string> written;
    for (auto& node : doc["nodes"]) {
        std::string id = node.value("id", "");
        for (const auto& k : knobs)
            if (k == "bias." + id) {
                node["inputs"]["bias"] = value;
                written.push_back(id);
            }
    }
    // The step factor lives in the scene settings; 1 is the default and is not written.
    if (factor < 1.0) doc["scene"]["step_factor"] = factor;
    else if (doc.contains("scene") && doc["scene"].is_object()) doc["scene"].erase("step_factor");
    std::ofstream out(graph, std::ios::binary | std::ios::trunc);
    out << format_graph_text(doc);
    if (!out) {
        fmt::print(stderr, "{}: cannot write\n", graph);
        return 1;
    }
    fmt::print("wrote bias {:.2f} into {} (node{} {}){}\n", value, graph, written.size() == 1 ? "" : "s",
               fmt::join(written, ", "), factor < 1.0 ? fmt::format(" and step factor {:.2f} into /scene/step_factor", factor) : "");
    return 0;
}

}  // namespace fg::fgc
