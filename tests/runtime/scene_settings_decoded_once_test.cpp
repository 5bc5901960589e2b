// The runtime decodes a pack's scene settings once, when the pack is read: never per frame, per
// pass or per view (they used to be parsed again from the manifest's JSON in eight places).
#include <gtest/gtest.h>

#include "graph/scene_settings.h"
#include "runtime_test_support.h"

namespace fg {
namespace {

class SceneSettingsDecodedOnce : public test::RuntimeTest {};

TEST_F(SceneSettingsDecodedOnce, reading_a_pack_decodes_them_and_30_headless_frames_decode_them_no_more) {
    // A scene with fog; foveation as the scene says (the frame graph looks for its block).
    Diagnostics diag;
    auto compiled = compile_graph(test::read_source_file("graphs/gallery/menger.json"), NodeLibrary::builtin(), {}, diag);
    ASSERT_TRUE(compiled) << diag.format();
    const std::vector<std::uint8_t> bytes = pack_bytes(*compiled);

    const std::uint64_t before_reading = scene_settings_parse_count();
    auto pack = read_pack(bytes, diag);
    ASSERT_TRUE(pack) << diag.format();
    const std::uint64_t after_reading = scene_settings_parse_count();
    EXPECT_EQ(after_reading, before_reading + 1) << "the pack reader decodes the scene once";

    FrameSettings frame;
    frame.width = 32;
    frame.height = 32;
    StereoSettings stereo;
    stereo.world_scale = pack->manifest.scene.world_scale;
    HeadlessRenderer renderer(test::shared_context(), *pack, frame, stereo);
    const HeadPose head = renderer.scene_camera();
    for (std::uint32_t f = 0; f < 30; ++f) renderer.render(head, f / 90.0, f);
    EXPECT_EQ(scene_settings_parse_count(), after_reading) << "scene settings were parsed while rendering";
}

}  // namespace
}  // namespace fg
