// The compiler finds scenes that repeat through space (every use of the position goes through one
// xform.repeat with a constant period) and records the period in the manifest; the runtime wraps
// the head by it. Anything else is not periodic, and says why.
#include <gtest/gtest.h>

#include "analysis/periodicity.h"
#include "pack/manifest.h"
#include "test_support.h"

using nlohmann::json;

namespace {

json lattice(const json& period) {
    return json::parse(R"({
      "format": "fractograph-graph", "version": 1, "name": "lattice",
      "params": {"cell": {"type": "vec3", "default": [2, 2, 2], "min": 0.5, "max": 4}},
      "nodes": [
        {"id": "cell", "type": "xform.repeat", "inputs": {}},
        {"id": "ball", "type": "prim.sphere", "inputs": {"p": "cell.p", "radius": 0.4}},
        {"id": "tone", "type": "palette.cosine", "inputs": {"t": 0.3}}
      ],
      "outputs": {"distance": "ball.distance", "albedo": "tone.color"}
    })")
        .patch(json::array({{{"op", "add"}, {"path", "/nodes/0/inputs/period"}, {"value", period}}}));
}

fg::Periodicity analyse(const json& g) {
    fg::Diagnostics diag;
    auto ir = fg::load_and_lower(g.dump(), fg::NodeLibrary::builtin(), diag);
    EXPECT_TRUE(ir) << diag.format();
    return ir ? fg::analyse_periodicity(*ir) : fg::Periodicity{};
}

}  // namespace

TEST(Periodicity, a_scene_repeated_from_the_position_with_a_constant_period_is_periodic_with_that_period) {
    auto p = analyse(lattice({2.0, 3.0, 4.0}));
    ASSERT_TRUE(p.period) << p.reason;
    EXPECT_EQ(*p.period, (std::array<double, 3>{2.0, 3.0, 4.0}));
}

TEST(Periodicity, a_period_bound_to_a_param_is_not_recorded_because_the_runtime_may_change_it) {
    auto p = analyse(lattice("$cell"));
    EXPECT_FALSE(p.period);
    EXPECT_NE(p.reason.find("\"cell\""), std::string::npos) << p.reason;
}

TEST(Periodicity, a_scene_that_also_reads_the_position_directly_is_not_periodic_and_names_the_node) {
    json g = lattice({2.0, 2.0, 2.0});
    g["nodes"].push_back({{"id", "floor"}, {"type", "prim.plane"}, {"inputs", json::object()}});
    g["nodes"].push_back({{"id", "both"}, {"type", "op.union"}, {"inputs", {{"a", "ball.distance"}, {"b", "floor.distance"}}}});
    g["outputs"]["distance"] = "both.distance";
    auto p = analyse(g);
    EXPECT_FALSE(p.period);
    EXPECT_NE(p.reason.find("\"floor\""), std::string::npos) << p.reason;
}

TEST(Periodicity, a_colour_that_reads_the_position_without_the_repetition_breaks_periodicity) {
    json g = lattice({2.0, 2.0, 2.0});
    g["nodes"].push_back({{"id", "here"}, {"type", "input.position"}, {"inputs", json::object()}});
    g["nodes"].push_back({{"id", "where"}, {"type", "math.length"}, {"inputs", {{"v", "here.value"}}}});
    g["nodes"].push_back({{"id", "shade"}, {"type", "palette.cosine"}, {"inputs", {{"t", "where.value"}}}});
    g["outputs"]["albedo"] = "shade.color";
    auto p = analyse(g);
    EXPECT_FALSE(p.period) << "colours would jump at a wrap";
}

TEST(Periodicity, the_gallery_mandelbulb_is_not_periodic) {
    auto p = analyse(json::parse(fg::test::read_source_file("graphs/gallery/mandelbulb.json")));
    EXPECT_FALSE(p.period);
}

TEST(Periodicity, the_manifest_keeps_the_period_and_reads_packs_without_one) {
    fg::PackManifest m;
    m.name = "m";
    m.period = std::array<double, 3>{2.0, 2.5, 3.0};
    json j = json::parse(fg::manifest_to_json(m).dump());   // as stored in a pack
    fg::Diagnostics diag;
    auto back = fg::manifest_from_json(j, diag);
    ASSERT_TRUE(back) << diag.format();
    ASSERT_TRUE(back->period);
    EXPECT_EQ(*back->period, *m.period);

    j.erase("period");   // a pack from before the period was recorded
    auto old = fg::manifest_from_json(j, diag);
    ASSERT_TRUE(old) << diag.format();
    EXPECT_FALSE(old->period);

    j["period"] = {2.0, -1.0, 3.0};
    fg::Diagnostics bad;
    EXPECT_FALSE(fg::manifest_from_json(j, bad) && !bad.has_errors());
    EXPECT_NE(bad.format().find("/period"), std::string::npos) << bad.format();
}
