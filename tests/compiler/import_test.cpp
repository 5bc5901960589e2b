// fgc import: Mandelbulber settings files made graphs. The file's reading (decimal commas, line
// numbers), the camera's axes and angle, hybrids' schedules, and the refusals that name what is
// not imported. That the imported shapes are Mandelbulber2's own is measured against its renders
// by bench/mandelbulber2/import_silhouettes.py.
#include <gtest/gtest.h>

#include <cmath>

#include "import/mandelbulber_import.h"
#include "test_support.h"

using namespace fg;
using nlohmann::ordered_json;

namespace {

std::optional<ordered_json> import_text(const std::string& text, Diagnostics& diag) {
    auto settings = FractSettings::parse(text, diag);
    return settings ? import_mandelbulber(*settings, "scene", diag) : std::nullopt;
}

bool said(const Diagnostics& diag, Severity severity, const std::string& text) {
    for (const auto& d : diag.items())
        if (d.severity == severity && d.message.find(text) != std::string::npos) return true;
    return false;
}

const char* kHeader = "# Mandelbulber settings file\n# version 2.20\n[main_parameters]\n";

}  // namespace

TEST(FractSettings, reads_decimal_commas_and_vectors_and_names_the_line_of_a_bad_one) {
    Diagnostics diag;
    auto s = FractSettings::parse(std::string(kHeader) + "camera 2,5 -1,25 3;\nN 12;\n[fractal_1]\npower 8,5;\n[frames]\nframe;a;b\n", diag);
    ASSERT_TRUE(s) << diag.format();
    EXPECT_EQ(fract_vector(s->find("camera")->text), glm::dvec3(2.5, -1.25, 3.0));
    EXPECT_EQ(fract_number(s->find("power", "fractal_1")->text), 8.5);
    EXPECT_EQ(s->find("power", "fractal_1")->line, 7);
    EXPECT_EQ(fract_number("1e-3"), 0.001);
    EXPECT_FALSE(fract_number("12abc"));
    EXPECT_FALSE(fract_vector("1 2"));

    Diagnostics bad;
    EXPECT_FALSE(FractSettings::parse(std::string(kHeader) + "camera 1 2 3\n", bad));
    EXPECT_TRUE(said(bad, Severity::Error, "line 4: expected 'name value;'")) << bad.format();
    Diagnostics other;
    EXPECT_FALSE(FractSettings::parse("[settings]\nx 1;\n", other));
    EXPECT_TRUE(said(other, Severity::Error, "no [main_parameters]")) << other.format();
}

TEST(MandelbulberImport, the_camera_turns_z_up_into_y_up_and_the_fov_into_degrees) {
    Diagnostics diag;
    auto g = import_text(std::string(kHeader) + "camera 3 -6 2;\ntarget 0 1 0;\ncamera_top 0 0 1;\nfov 0,5;\nformula_1 2;\n", diag);
    ASSERT_TRUE(g) << diag.format();
    const auto& cam = (*g)["scene"]["camera"];
    EXPECT_EQ(cam["position"], ordered_json({3.0, 2.0, 6.0}));
    EXPECT_EQ(cam["target"], ordered_json({0.0, 0.0, -1.0}));
    EXPECT_EQ(cam["up"], ordered_json({0.0, 1.0, -0.0}));
    // Three-point perspective: fov is 2 tan(angle / 2).
    EXPECT_NEAR(cam["fov_deg"].get<double>(), 2.0 * std::atan(0.25) * 180.0 / M_PI, 1e-9);
    // Mandelbulber's outer bound and its default view distance.
    EXPECT_EQ((*g)["scene"]["bounds"]["radius"], 100.0);
    EXPECT_EQ((*g)["scene"]["max_distance"], 50.0);
    EXPECT_FALSE((*g)["scene"].contains("step_fraction"));

    // DE_factor shortens the steps only: the step fraction, which hit tests divide back out.
    Diagnostics shorter;
    auto s = import_text(std::string(kHeader) + "DE_factor 0,25;\nformula_1 2;\n", shorter);
    ASSERT_TRUE(s) << shorter.format();
    EXPECT_EQ((*s)["scene"]["step_fraction"], 0.25);
    Diagnostics longer;
    auto o = import_text(std::string(kHeader) + "DE_factor 1,5;\nformula_1 2;\n", longer);
    ASSERT_TRUE(o) << longer.format();
    EXPECT_FALSE((*o)["scene"].contains("step_fraction"));
    EXPECT_TRUE(said(longer, Severity::Warning, "DE_factor 1.5: not imported")) << longer.format();

    // Mandelbulber 2.10 and older drew the picture flipped top to bottom: the world mirrored in y,
    // seen with the camera's top reversed.
    Diagnostics legacy;
    auto l = import_text(std::string(kHeader) + "legacy_coordinate_system true;\ncamera 3 -6 2;\ncamera_top 0 0,6 0,8;\nformula_1 8;\n", legacy);
    ASSERT_TRUE(l) << legacy.format();
    EXPECT_EQ((*l)["scene"]["camera"]["position"], ordered_json({3.0, 2.0, -6.0}));
    EXPECT_EQ((*l)["scene"]["camera"]["up"], ordered_json({-0.0, -0.8, -0.6}));
}

TEST(MandelbulberImport, a_hybrid_runs_its_slots_in_order_for_their_counts_over_and_over_and_compiles) {
    Diagnostics diag;
    auto g = import_text(std::string(kHeader) +
                             "hybrid_fractal_enable true;\nformula_1 8;\nformula_2 2;\nformula_iterations_1 2;\nN 12;\n"
                             "fractal_constant_factor 0,9 0,9 0,9;\n[fractal_1]\nmandelbox_scale -1,5;\n[fractal_2]\npower 2;\n",
                         diag);
    ASSERT_TRUE(g) << diag.format();
    const auto& f = (*g)["nodes"][0];
    EXPECT_EQ(f["type"], "fractal.formula");
    EXPECT_EQ(f["inputs"]["iterations"], 12);
    EXPECT_EQ(f["inputs"]["bailout"], 100.0);   // the larger of the formulas' own
    const auto& body = f["formula"];
    ASSERT_EQ(body["groups"].size(), 2u);
    EXPECT_EQ(body["groups"][0]["name"], "slot1_mandelbox");
    EXPECT_EQ(body["groups"][1]["name"], "slot2_mandelbulb");
    EXPECT_EQ(body["schedule"], ordered_json::parse(R"([{"group": "slot1_mandelbox", "count": 2}, {"group": "slot2_mandelbulb", "count": 1}])"));
    EXPECT_TRUE(body["repeat"].get<bool>());
    EXPECT_EQ(body["groups"][0]["nodes"][2]["inputs"]["scale"], -1.5);
    EXPECT_EQ(body["groups"][0]["nodes"][3]["id"], "s1_add");
    EXPECT_EQ(body["groups"][0]["nodes"][3]["inputs"]["weight"], 0.9);
    EXPECT_EQ(body["groups"][1]["nodes"][0]["type"], "stage.triplex_power_elevation");
    Diagnostics compile;
    EXPECT_TRUE(test::compile_text(g->dump(), compile)) << compile.format();
}

TEST(MandelbulberImport, iteration_windows_keep_each_slot_to_its_iterations) {
    // The sequence 1 1 2 1 1 2 ..., slot 1 only up to iteration 3, slot 2 from iteration 2: 1 1 2 1
    // (1) 2 (1 1) 2 ... with the skipped iterations leaving z alone; of N = 20, slot 2's last at 17.
    Diagnostics diag;
    auto g = import_text(std::string(kHeader) +
                             "hybrid_fractal_enable true;\nformula_1 8;\nformula_2 7;\nformula_iterations_1 2;\nN 20;\n"
                             "formula_stop_iteration_1 3;\nformula_start_iteration_2 2;\n",
                         diag);
    ASSERT_TRUE(g) << diag.format();
    const auto& body = (*g)["nodes"][0]["formula"];
    EXPECT_EQ(body["schedule"], ordered_json::parse(R"([{"group": "slot1_mandelbox", "count": 2}, {"group": "slot2_menger_sponge", "count": 1},
                                                      {"group": "slot1_mandelbox", "count": 1}, {"group": "slot2_menger_sponge", "count": 5}])"))
        << body.dump();
    EXPECT_FALSE(body.contains("repeat"));

    Diagnostics alternating;
    EXPECT_FALSE(import_text(std::string(kHeader) + "hybrid_fractal_enable true;\nformula_1 8;\nformula_2 7;\nN 100;\n"
                                                    "formula_start_iteration_1 1;\n", alternating));
    EXPECT_TRUE(said(alternating, Severity::Error, "runs of one formula; at most 16 are imported")) << alternating.format();
}

TEST(MandelbulberImport, what_changes_the_shape_and_is_not_imported_is_an_error_naming_its_line) {
    struct Case {
        std::string settings, message;
    };
    const Case cases[] = {
        {"formula_1 19;\n", "line 4: formula_1 19: this formula is not imported (imported: 2 mandelbulb, 3 mandelbulb_power2, 4 hypercomplex"},
        {"formula_1 8;\n[fractal_1]\nmandelbox_folding_value 3;\n",
         "line 6: [fractal_1] mandelbox_folding_value: formula 8 (mandelbox): a fold to 3 - z beyond 1 is not a reflection"},
        {"formula_1 10;\n[fractal_1]\nIFS_enabled_2 true;\nIFS_intensity_2 0,5;\n",
         "line 7: [fractal_1] IFS_intensity_2: formula 10 (kaleidoscopic_ifs): a fold of intensity 0.5 is not a reflection"},
        {"formula_1 2;\nboolean_operators true;\n", "line 5: boolean_operators: true is not imported"},
        {"formula_1 2;\nprimitive_water_1_enabled true;\n", "line 5: primitive_water_1_enabled: a water primitive is not imported"},
        {"formula_1 2;\nprimitive_sphere_1_enabled true;\nprimitive_sphere_1_empty true;\n", "line 6: primitive_sphere_1_empty: true is not imported (a hollow primitive)"},
        {"formula_1 2;\nperspective_type fish_eye;\n", "line 5: perspective_type: fish_eye is not imported"},
        {"hybrid_fractal_enable true;\nformula_1 2;\nformula_2 4;\n", "a hybrid of 3D and four-dimensional formulas is not imported"},
        {"hybrid_fractal_enable true;\nformula_1 2;\nformula_2 103;\n", "a pseudo-Kleinian in a hybrid with other formulas is not imported"},
        {"hybrid_fractal_enable true;\nformula_1 2;\ncheck_for_bailout_1 false;\n", "line 6: check_for_bailout_1: false is not imported"},
        {"formula_1 2;\nfractal_constant_factor 1 0 1;\n", "c scaled unevenly"},
        {"hybrid_fractal_enable true;\nformula_1 2;\nrepeat_from 2;\n", "line 6: repeat_from: 2 is not imported"},
        {"formula_1 2;\nN many;\n", "line 5: N: 'many' is not a number"},
    };
    for (const auto& c : cases) {
        Diagnostics diag;
        EXPECT_FALSE(import_text(std::string(kHeader) + c.settings, diag)) << c.settings;
        EXPECT_TRUE(said(diag, Severity::Error, c.message)) << c.settings << "\n" << diag.format();
    }
}

TEST(MandelbulberImport, the_look_is_named_in_a_warning_and_limits_cut_the_shape_with_a_box) {
    Diagnostics diag;
    auto g = import_text(std::string(kHeader) +
                             "formula_1 8;\nglow_intensity 0,5;\nambient_occlusion_enabled true;\nlimits_enabled true;\n"
                             "limit_min -1 -2 -3;\nlimit_max 1 2 3;\ndetail_level 2;\n",
                         diag);
    ASSERT_TRUE(g) << diag.format();
    EXPECT_TRUE(said(diag, Severity::Warning, "2 settings of the look are not imported")) << diag.format();
    EXPECT_TRUE(said(diag, Severity::Warning, "glow_intensity")) << diag.format();
    EXPECT_TRUE(said(diag, Severity::Warning, "fgplay --detail 2")) << diag.format();
    EXPECT_EQ((*g)["outputs"]["distance"], "cut.distance");
    const auto& box = (*g)["nodes"][7];
    EXPECT_EQ(box["type"], "prim.box");
    EXPECT_EQ(box["inputs"]["size"], ordered_json({1.0, 3.0, 2.0}));   // z up there is y up here
    Diagnostics compile;
    EXPECT_TRUE(test::compile_text(g->dump(), compile)) << compile.format();
}
