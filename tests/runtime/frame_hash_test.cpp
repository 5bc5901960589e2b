// Refactoring the runtime must not move a single bit of a frame: every gallery graph (and the
// double-precision deep zoom) in every stereo mode, with and without the lens mask and foveation,
// hashes to what tests/runtime/data/frame_hashes.txt recorded before the change. A change that is
// meant to alter frames re-records the file (FG_RECORD_FRAME_HASHES=1) and says why in its commit.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <sstream>
#include <xxhash.h>

#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

const char* kHashFile = "tests/runtime/data/frame_hashes.txt";

struct Case {
    std::string graph;     // "gallery/mandelbulb"
    StereoMode stereo;
    bool fewer_pixels;     // lens mask and foveation 0.4
    std::string key() const {
        return fmt::format("{} {} {}", graph, stereo_mode_name(stereo), fewer_pixels ? "mask+foveation" : "full");
    }
};

std::vector<Case> cases() {
    std::vector<std::string> graphs;
    for (const auto& g : test::source_graph_names("graphs/gallery")) graphs.push_back("gallery/" + g);
    graphs.push_back("hard/deep_zoom");
    std::vector<Case> out;
    for (const auto& g : graphs)
        for (auto mode : {StereoMode::Naive, StereoMode::PerEye, StereoMode::Reproject})
            for (bool fewer : {false, true}) out.push_back({g, mode, fewer});
    return out;
}

std::map<std::string, std::string> recorded() {
    std::map<std::string, std::string> m;
    std::istringstream in(test::read_source_file(kHashFile));
    std::string line;
    while (std::getline(in, line)) {
        auto at = line.rfind(' ');
        if (line.empty() || line[0] == '#' || at == std::string::npos) continue;
        m[line.substr(0, at)] = line.substr(at + 1);
    }
    return m;
}

// Both eyes' final images and depths, as the headless renderer downloads them.
std::string frame_hash(const RenderedFrame& f) {
    XXH64_state_t* s = XXH64_createState();
    XXH64_reset(s, 0);
    XXH64_update(s, f.left.pixels.data(), f.left.pixels.size());
    XXH64_update(s, f.right.pixels.data(), f.right.pixels.size());
    XXH64_update(s, f.depth_left.data(), f.depth_left.size() * sizeof(float));
    XXH64_update(s, f.depth_right.data(), f.depth_right.size() * sizeof(float));
    std::uint64_t h = XXH64_digest(s);
    XXH64_freeState(s);
    return fmt::format("{:016x}", h);
}

class FrameHashes : public RuntimeTest {};

}  // namespace

TEST_F(FrameHashes, every_gallery_frame_is_bit_identical_to_the_recorded_one) {
    const bool record = std::getenv("FG_RECORD_FRAME_HASHES") != nullptr;
    const auto expected = recorded();
    std::map<std::string, Pack> packs;
    std::string lines = "# graph stereo pixels xxh64(left, right, depth left, depth right); 52x40 per eye, scene camera\n";
    for (const auto& c : cases()) {
        auto it = packs.find(c.graph);
        if (it == packs.end())
            it = packs.emplace(c.graph, test::compile_pack(test::read_source_file("graphs/" + c.graph + ".json"),
                                                          std::filesystem::path("graphs/" + c.graph).parent_path().string())).first;
        FrameSettings fs;
        // Not a multiple of the 8x8 workgroups, so edge groups are covered.
        fs.width = 52;
        fs.height = 40;
        fs.cone_levels = 4;
        fs.stereo = c.stereo;
        fs.lens_mask = c.fewer_pixels;
        fs.foveation = c.fewer_pixels ? 0.4 : 0.0;
        HeadlessRenderer renderer(test::shared_context(), it->second, fs, StereoSettings{});
        std::string hash = frame_hash(renderer.render(renderer.scene_camera(), 0.0));
        lines += c.key() + " " + hash + "\n";
        if (record) continue;
        auto want = expected.find(c.key());
        ASSERT_NE(want, expected.end()) << c.key() << " has no recorded hash: record with FG_RECORD_FRAME_HASHES=1";
        EXPECT_EQ(hash, want->second) << c.key() << ": the frame changed";
    }
    if (record) {
        std::ofstream(std::string(FG_SOURCE_DIR) + "/" + kHashFile) << lines;
        GTEST_SKIP() << "recorded " << kHashFile;
    }
}
