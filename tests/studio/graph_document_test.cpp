#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "javascript_json.h"
#include "studio/graph_document.h"

namespace fg::studio {

namespace {
std::string read(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

nlohmann::ordered_json as_javascript_sends_it(const std::string& text) {
    auto j = nlohmann::ordered_json::parse(text);
    test::as_javascript_writes_it(j);
    return j;
}
}  // namespace

TEST(GraphDocument, EveryGalleryGraphSavesByteIdenticalWhenUntouched) {
    int checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(FG_SOURCE_DIR) + "/graphs/gallery")) {
        if (entry.path().extension() != ".json") continue;   // the sky image beside the graphs
        std::string text = read(entry.path());
        auto original = nlohmann::ordered_json::parse(text);
        EXPECT_EQ(canonical_graph_text(as_javascript_sends_it(text), &original), text) << entry.path();
        ++checked;
    }
    EXPECT_GE(checked, 13);
}

TEST(GraphDocument, AnEditedValueIsWrittenAsEdited) {
    auto original = nlohmann::ordered_json::parse(R"({"format": "fractograph-graph", "version": 1, "x": 8.0, "y": [1.0, 2.5]})");
    auto edited = nlohmann::ordered_json::parse(R"({"format": "fractograph-graph", "version": 1, "x": 7, "y": [1, 2.5], "z": 3})");
    EXPECT_EQ(canonical_graph_text(edited, &original),
              "{\n  \"format\": \"fractograph-graph\",\n  \"version\": 1,\n  \"x\": 7,\n  \"y\": [1.0, 2.5],\n  \"z\": 3\n}\n");
}

}  // namespace fg::studio
