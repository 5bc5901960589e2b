// fgc check and compile advise "precision": "double" where a float scene's coordinates are too
// large for float, and nowhere else.
#include <gtest/gtest.h>

#include "analysis/precision_advice.h"
#include "test_support.h"

namespace fg {
namespace {

std::optional<IrGraph> lower(const std::string& text) {
    Diagnostics diag;
    auto ir = load_and_lower(text, NodeLibrary::builtin(), diag);
    EXPECT_FALSE(diag.has_errors()) << diag.format();
    return ir;
}

const Diagnostic* precision_warning(const Diagnostics& diag) {
    for (const auto& d : diag.items())
        if (d.severity == Severity::Warning && d.message.find("\"precision\": \"double\"") != std::string::npos) return &d;
    return nullptr;
}

TEST(PrecisionAdvice, FloatSpacingIsOneUnitInTheLastPlace) {
    EXPECT_EQ(float_spacing(1.0), std::ldexp(1.0, -23));
    EXPECT_EQ(float_spacing(1e6), 0.0625);
    EXPECT_EQ(float_spacing(-3.0), std::ldexp(1.0, -22));
}

TEST(PrecisionAdvice, AMengerAMillionUnitsOutIsWarnedAboutAtItsCoordinates) {
    Diagnostics diag;
    auto result = test::compile_text(test::read_source_file("tests/compiler/graphs/precision/far_menger.json"), diag);
    ASSERT_TRUE(result) << diag.format();
    const Diagnostic* w = precision_warning(diag);
    ASSERT_NE(w, nullptr) << diag.format();
    EXPECT_EQ(w->pointer, "/scene/camera/position");   // the largest of the coordinates, all near 1e6
    EXPECT_NE(w->message.find("0.0625 apart in float"), std::string::npos) << w->message;
    EXPECT_FALSE(diag.has_errors());   // advice: the pack is still written

    auto ir = lower(test::read_source_file("tests/compiler/graphs/precision/far_menger.json"));
    ASSERT_TRUE(ir);
    const PrecisionAdvice a = float_precision_advice(*ir);
    EXPECT_TRUE(a.too_coarse);
    EXPECT_GT(a.spacing, 10.0 * a.hit_threshold);
}

TEST(PrecisionAdvice, TheSameMengerInDoubleIsNotWarnedAbout) {
    auto j = nlohmann::json::parse(test::read_source_file("tests/compiler/graphs/precision/far_menger.json"));
    j["scene"]["precision"] = "double";
    Diagnostics diag;
    ASSERT_TRUE(test::compile_text(j.dump(), diag)) << diag.format();
    EXPECT_EQ(precision_warning(diag), nullptr) << diag.format();
}

TEST(PrecisionAdvice, AShapeTranslatedOutsideTheBoundsIsNeverReachedAndNotCounted) {
    auto j = nlohmann::json::parse(test::read_source_file("tests/compiler/graphs/precision/far_menger.json"));
    j["scene"]["camera"] = {{"position", {2.1, 1.5, 2.6}}, {"target", {0.0, -0.1, 0.0}}};
    j["scene"]["bounds"] = {{"radius", 1.8}};
    auto ir = lower(j.dump());
    ASSERT_TRUE(ir);
    EXPECT_FALSE(float_precision_advice(*ir).too_coarse);
}

TEST(PrecisionAdvice, NoGalleryOrExampleOrFloatHardCaseIsWarnedAbout) {
    std::vector<std::string> graphs = test::graph_files("graphs/gallery");
    for (const char* folder : {"graphs/examples", "graphs/hard"})
        for (const auto& g : test::graph_files(folder)) graphs.push_back(g);
    for (const auto& path : graphs) {
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        auto ir = lower(text.str());
        ASSERT_TRUE(ir) << path;
        Diagnostics diag;
        advise_precision(*ir, diag);
        EXPECT_EQ(precision_warning(diag), nullptr) << path << ":\n" << diag.format();
    }
}

TEST(PrecisionAdvice, TheDeepZoomCompiledInFloatIsWarnedAbout) {
    auto ir = lower(test::read_source_file("graphs/hard/deep_zoom.json"));
    ASSERT_TRUE(ir);
    ir->scene.double_precision = false;
    Diagnostics diag;
    advise_precision(*ir, diag);
    EXPECT_NE(precision_warning(diag), nullptr);
}

}  // namespace
}  // namespace fg
