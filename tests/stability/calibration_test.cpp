// The bubble search behind `fgc calibrate`: it finds the overshoots of an unguarded distance
// estimate, finds none at the bias a graph was calibrated with, and gives the same answer on any
// thread count. Every fractal node of the library is covered without naming it.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "analysis/bubble_search.h"
#include "analysis/lipschitz_bound.h"
#include "hard_case_support.h"

using namespace fg;
using namespace fg::test;

namespace {

struct Lowered {
    IrGraph ir;
    std::optional<CpuEvaluator> cpu;
    double step_scale = 1.0;
};

std::unique_ptr<Lowered> lower(const std::string& text) {
    auto out = std::make_unique<Lowered>();
    Diagnostics diag;
    auto ir = load_and_lower(text, NodeLibrary::builtin(), diag);
    if (!ir) throw std::runtime_error(diag.format());
    out->ir = std::move(*ir);
    out->cpu = CpuEvaluator::create(out->ir, diag);
    if (!out->cpu) throw std::runtime_error(diag.format());
    // The march's step scale: the calibrated step factor over the Lipschitz bound.
    out->step_scale = out->ir.scene.step_factor / analyse_lipschitz(out->ir, diag).bound;
    return out;
}

// The bias a graph's fractal nodes carry (the calibrated value, or the node's default).
double graph_bias(const IrGraph& ir) {
    double bias = 0.0;
    for (const auto& n : ir.nodes)
        for (std::size_t i = 0; i < n.inputs.size(); ++i)
            if (n.inputs[i].kind == IrInput::Kind::Knob && n.def->inputs[i].knob == "bias") bias = n.inputs[i].constant.v[0];
    return bias;
}

BubbleSearch searched(const Lowered& g, int samples, std::uint64_t seed, int threads = 2) {
    BubbleSearchSettings s;
    s.samples = samples;
    s.seed = seed;
    s.threads = threads;
    s.reach_step = g.step_scale / g.ir.scene.step_factor;
    BubbleSearch search(*g.cpu, s);
    search.run();
    return search;
}

class CalibratedHardCase : public ::testing::TestWithParam<std::string> {};
class CalibratedGalleryGraph : public ::testing::TestWithParam<std::string> {};


}  // namespace

TEST(BubbleSearch, finds_overshoots_with_the_bias_off_and_none_at_the_calibrated_bias) {
    // The power-8 bulb seen down its pole, calibrated by fgc calibrate (bias and step factor).
    auto g = lower(hard_case_text("axes_and_poles"));
    BubbleSearch search = searched(*g, 3000, 1);
    const double full_steps = g->step_scale / g->ir.scene.step_factor;
    OvershootCount off = search.count(0.0, full_steps);
    OvershootCount on = search.count(graph_bias(g->ir), g->step_scale);
    RecordProperty("bias_off", fmt::format("{} of {} samples overshoot, worst {:.2f}x", off.overshoots, off.samples, off.worst));
    EXPECT_GT(off.samples, 2500u);
    EXPECT_GT(off.overshoots, 0u) << "without the guard the Mandelbulb's estimate overshoots";
    EXPECT_EQ(on.overshoots, 0u) << "at the calibrated bias " << graph_bias(g->ir);
    // The guard matters: at the calibrated step factor but without the bias the overshoots stay.
    EXPECT_GT(search.count(0.0, g->step_scale).overshoots, 0u);
}

TEST(BubbleSearch, gives_the_same_answer_on_any_thread_count) {
    auto g = lower(read_source_file("graphs/gallery/mandelbulb.json"));
    BubbleSearch one = searched(*g, 120, 5, 1), three = searched(*g, 120, 5, 3);
    ASSERT_EQ(one.samples().size(), three.samples().size());
    for (std::size_t i = 0; i < one.samples().size(); ++i) {
        EXPECT_EQ(one.samples()[i].p, three.samples()[i].p);
        EXPECT_EQ(one.samples()[i].interior, three.samples()[i].interior);
    }
    EXPECT_EQ(one.smallest_safe_bias(g->step_scale, 0.0, 4.0), three.smallest_safe_bias(g->step_scale, 0.0, 4.0));
}

TEST(BubbleSearch, every_fractal_node_has_a_safe_bias_within_its_range) {
    std::size_t fractals = 0;
    for (const auto& def : NodeLibrary::builtin().all()) {
        if (def->running_derivative.empty() || def->generated_body()) continue;  // formulas: formula_test.cpp
        ++fractals;
        std::string text = fmt::format(R"({{"format": "fractograph-graph", "version": 1,
            "nodes": [{{"id": "f", "type": "{}"}}], "outputs": {{"distance": "f.distance"}},
            "scene": {{"bounds": {{"radius": 2.0}}}}}})", def->type);
        auto g = lower(text);
        ASSERT_EQ(BubbleSearch::bias_knobs(g->ir).size(), 1u) << def->type;
        double max_bias = 4.0;
        for (const auto& port : def->inputs)
            if (port.knob == "bias" && port.max) max_bias = *port.max;
        BubbleSearch search = searched(*g, 300, 3);
        // The node's own range, at full steps or at the smallest step factor calibrate may write.
        auto safe = search.smallest_safe_bias(g->step_scale, 0.0, max_bias);
        if (!safe) safe = search.smallest_safe_bias(0.5 * g->step_scale, 0.0, max_bias);
        RecordProperty(def->type, safe ? fmt::format("{:.2f}", *safe) : std::string("none"));
        EXPECT_TRUE(safe.has_value()) << def->type << ": no bias up to " << max_bias << " removes the overshoots";
    }
    EXPECT_GE(fractals, 1u);
}

TEST_P(CalibratedHardCase, the_bubble_search_finds_no_overshoot_at_the_graph_bias) {
    auto g = lower(hard_case_text(GetParam()));
    if (BubbleSearch::bias_knobs(g->ir).empty()) GTEST_SKIP() << "no fractal with a bias knob";
    // A seed the calibration did not use: the bias must hold beyond the samples it was chosen on.
    BubbleSearch search = searched(*g, 300, 11);
    OvershootCount c = search.count(graph_bias(g->ir), g->step_scale);
    RecordProperty("overshoots", fmt::format("{} of {} at bias {}", c.overshoots, c.samples, graph_bias(g->ir)));
    EXPECT_GT(c.samples, 200u);
    EXPECT_EQ(c.overshoots, 0u) << "bias " << graph_bias(g->ir) << ", worst step " << c.worst << "x the free distance";
}

// The gallery is what users start from: every fractal there carries the bias fgc calibrate chose
// (not the node's default). On samples the calibration did not see, it keeps the surface the march
// sees within the growth budget and leaves no more overshoots than the unguarded estimate.
TEST_P(CalibratedGalleryGraph, carries_a_calibrated_bias_that_keeps_the_surface_and_cuts_overshoots) {
    const std::string& name = GetParam();
    std::string text = read_source_file((name.find('/') == std::string::npos ? "graphs/gallery/" : "graphs/") + name + ".json");
    auto g = lower(text);
    auto knobs = BubbleSearch::bias_knobs(g->ir);
    if (knobs.empty()) GTEST_SKIP() << "no fractal with a bias knob";
    auto doc = nlohmann::json::parse(text);
    for (const auto& node : doc["nodes"])
        for (const auto& k : knobs)
            if (k == "bias." + node["id"].get<std::string>())
                EXPECT_TRUE(node.contains("inputs") && node["inputs"].contains("bias"))
                    << "node '" << node["id"].get<std::string>() << "' has no calibrated bias: run fgc calibrate";
    BubbleSearch search = searched(*g, 1000, 11);
    const double bias = graph_bias(g->ir);
    OvershootCount on = search.count(bias, g->step_scale), off = search.count(0.0, g->step_scale / g->ir.scene.step_factor);
    SurfaceGrowth growth = search.surface_growth(bias);
    RecordProperty("overshoots", fmt::format("{} of {} at bias {} ({} unguarded), surface growth {:.2f}x", on.overshoots,
                                             on.samples, bias, off.overshoots, growth.p90));
    EXPECT_GT(on.samples, 700u);
    EXPECT_LE(on.overshoots, off.overshoots) << "bias " << bias;
    // fgc calibrate's default budget is 2; unseen samples may read a little higher.
    EXPECT_LE(growth.p90, 2.5) << "bias " << bias << " moves the visible surface " << growth.p90 << " hit thresholds";
}

// The budget is what keeps calibration from ruining a scene: the bias that removes the Julia
// pool's last overshoots shrinks the estimate near the visible surface so much that a smooth union
// with the floor digs a false interior (the scene melts into a blob), and the growth says so.
TEST(BubbleSearch, the_surface_growth_exposes_a_bias_that_melts_the_scene) {
    auto g = lower(read_source_file("graphs/gallery/julia_pool.json"));
    BubbleSearch search = searched(*g, 1000, 1);
    // What `fgc calibrate --max-growth 0` writes (10000 samples: the overshoots are too rare for
    // a thousand to find them all).
    std::optional<double> strict = 3.96;
    SurfaceGrowth melted = search.surface_growth(*strict), kept = search.surface_growth(graph_bias(g->ir));
    RecordProperty("growth", fmt::format("bias {:.2f}: {:.3g}x; calibrated bias {}: {:.2f}x", *strict, melted.p90,
                                         graph_bias(g->ir), kept.p90));
    EXPECT_GT(melted.p90, 5.0) << "bias " << *strict;
    EXPECT_LE(kept.p90, 2.0);
    EXPECT_GT(search.visible_surface().size(), 100u) << "the start view's rays should meet the surface";
}

INSTANTIATE_TEST_SUITE_P(Gallery, CalibratedGalleryGraph, ::testing::ValuesIn(source_graph_names("graphs/gallery")),
                         [](const auto& info) { return test_name(info.param); });

INSTANTIATE_TEST_SUITE_P(Cases, CalibratedHardCase, ::testing::ValuesIn(hard_case_names()),
                         [](const auto& info) { return test_name(info.param); });
// Formula graphs meet the gallery's standard; the hybrids and all but the power-8 bulb are also free of overshoots
// (its bias, like the gallery bulb's, is the one with the fewest within the growth budget).
INSTANTIATE_TEST_SUITE_P(Formulas, CalibratedGalleryGraph, ::testing::ValuesIn(formula_case_names()),
                         [](const auto& info) { return test_name(info.param); });
INSTANTIATE_TEST_SUITE_P(Formulas, CalibratedHardCase, ::testing::Values("gallery/bulb_box_hybrid", "gallery/box_menger_hybrid", "formulas/mandelbox",
                                                                         "formulas/menger_twisted", "formulas/kleinian"),
                         [](const auto& info) { return test_name(info.param); });
