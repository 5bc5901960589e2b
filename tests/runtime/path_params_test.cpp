// Graph parameters keyed in a camera path: they move between the keys that name them with the
// path's interpolation and easing; names, sizes and ranges are checked against the pack with the
// keyframe field in every error; and a render of a path that sweeps the bulb's power from 8 to 4
// starts on the still frame at 8 and ends on the still frame at 4, one pack for every frame.
#include <gtest/gtest.h>

#include "offline/camera_path.h"
#include "offline/path_params.h"
#include "offline/path_render.h"
#include "runtime_test_support.h"

using namespace fg;

namespace {

std::optional<CameraPath> parse(const std::string& text, Diagnostics& diag) {
    return CameraPath::parse(nlohmann::json::parse(text), 1.0, diag);
}

// Power keyed at the first and last of three keys, hue at the middle one only.
const char* kPowerSweep = R"({
  "format": "fractograph-camera-path", "version": 1, "fps": 4, "interpolation": "linear",
  "keyframes": [
    {"time": 0.0, "position": [0, 0.6, 2.6], "target": [0, 0, 0], "params": {"power": 8}, "ease": "in-out"},
    {"time": 0.5, "position": [0, 0.6, 2.6], "target": [0, 0, 0], "params": {"hue": 0.5}},
    {"time": 1.0, "position": [0, 0.6, 2.6], "target": [0, 0, 0], "params": {"power": 4}}
  ]
})";

// The same pose with nothing keyed.
const char* kStill = R"({
  "format": "fractograph-camera-path", "version": 1,
  "keyframes": [{"time": 0.0, "position": [0, 0.6, 2.6], "target": [0, 0, 0]}]
})";

}  // namespace

TEST(PathParams, a_parameter_moves_between_the_keys_that_name_it_with_their_easing) {
    Diagnostics diag;
    auto path = parse(kPowerSweep, diag);
    ASSERT_TRUE(path) << diag.format();
    EXPECT_DOUBLE_EQ(path->sample(0).params.at("power")[0], 8.0);
    EXPECT_DOUBLE_EQ(path->sample(4).params.at("power")[0], 4.0);
    // The power's own track runs from key 0 to key 2 (key 1 does not name it), eased in-out as key 0
    // asks: a quarter of the way in time is 15.6 % of the way in value.
    const double s = 0.25 * 0.25 * (3.0 - 2.0 * 0.25);
    EXPECT_NEAR(path->sample(1).params.at("power")[0], 8.0 - 4.0 * s, 1e-12);
    // A parameter keyed once holds that value over the whole path.
    EXPECT_DOUBLE_EQ(path->sample(0).params.at("hue")[0], 0.5);
    EXPECT_DOUBLE_EQ(path->sample(4).params.at("hue")[0], 0.5);
}

TEST(PathParams, unknown_names_wrong_sizes_and_values_out_of_range_name_the_keyframe_field) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    Diagnostics diag;
    auto path = parse(R"({"format": "fractograph-camera-path", "version": 1, "keyframes": [
        {"time": 0, "position": [0, 0, 3], "target": [0, 0, 0], "params": {"powr": 6}},
        {"time": 1, "position": [0, 0, 3], "target": [0, 0, 0], "params": {"power": [6, 7]}},
        {"time": 2, "position": [0, 0, 3], "target": [0, 0, 0], "params": {"power": 40, "hue": "red"}}]})",
                      diag);
    ASSERT_FALSE(path) << "a parameter that is not a number is refused while parsing";
    EXPECT_NE(diag.format().find("/keyframes/2/params/hue"), std::string::npos) << diag.format();
    diag = {};
    path = parse(R"({"format": "fractograph-camera-path", "version": 1, "keyframes": [
        {"time": 0, "position": [0, 0, 3], "target": [0, 0, 0], "params": {"powr": 6}},
        {"time": 1, "position": [0, 0, 3], "target": [0, 0, 0], "params": {"power": [6, 7]}},
        {"time": 2, "position": [0, 0, 3], "target": [0, 0, 0], "params": {"power": 40}}]})",
                 diag);
    ASSERT_TRUE(path) << diag.format();
    EXPECT_FALSE(check_path_params(*path, pack.manifest, diag));
    std::string text = diag.format();
    EXPECT_NE(text.find("/keyframes/0/params/powr"), std::string::npos) << text;
    EXPECT_NE(text.find("its parameters are: hue, power"), std::string::npos) << text;
    EXPECT_NE(text.find("/keyframes/1/params/power"), std::string::npos) << text;
    EXPECT_NE(text.find("/keyframes/2/params/power"), std::string::npos) << text;
    EXPECT_NE(text.find("outside its range [2, 16]"), std::string::npos) << text;
}

class PathParamsRender : public test::RuntimeTest {};

TEST_F(PathParamsRender, a_power_sweep_starts_and_ends_on_the_still_frames_with_one_pack) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    Diagnostics diag;
    auto path = parse(kPowerSweep, diag);
    ASSERT_TRUE(path) << diag.format();
    PathRenderSettings settings;
    settings.projection = Projection::Perspective;
    settings.width = settings.height = 48;
    // One renderer, one pack, every frame: parameters are uniforms, nothing recompiles.
    PathRenderer renderer(test::shared_context(), pack, *path, settings);
    Rgba8Image first = renderer.render(0), middle = renderer.render(2), last = renderer.render(4);

    // A still frame of the same pose from a pack whose parameters default to the keyed values.
    auto still = [&](double power) {
        Pack p = pack;
        for (auto& param : p.manifest.params) {
            if (param.name == "power") param.value.v[0] = power;
            if (param.name == "hue") param.value.v[0] = 0.5;
        }
        Diagnostics d;
        PathRenderer r(test::shared_context(), p, *parse(kStill, d), settings);
        return r.render(0);
    };
    EXPECT_EQ(first.pixels, still(8.0).pixels);
    EXPECT_EQ(last.pixels, still(4.0).pixels);
    EXPECT_NE(middle.pixels, first.pixels);
    EXPECT_NE(middle.pixels, last.pixels);
    EXPECT_EQ(renderer.render(4).pixels, last.pixels) << "a frame depends on its number only";
    EXPECT_EQ(renderer.render(0).pixels, first.pixels) << "rendering later frames first changes nothing";
}
