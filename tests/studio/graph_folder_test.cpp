#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scratch_dir.h"
#include "studio/graph_folder.h"

namespace fg::studio {

namespace fs = std::filesystem;

class GraphFolderTest : public ::testing::Test {
protected:
    void SetUp() override {
        fs::create_directories(base / "work" / "sub");
        std::ofstream(base / "work" / "a.json") << "{}";
        std::ofstream(base / "work" / "sub" / "b.json") << "{}";
        std::ofstream(base / "secret.json") << "{\"secret\": 1}";
        fs::create_symlink(base / "secret.json", base / "work" / "link.json");
    }
    fg::test::ScratchDir scratch{"fg_studio_folder"};
    fs::path base = scratch.path();
};

TEST_F(GraphFolderTest, ReadsAndWritesInsideTheFolder) {
    GraphFolder folder(base / "work");
    std::string error;
    EXPECT_EQ(folder.read("a.json", error), "{}");
    EXPECT_TRUE(folder.write("sub/new.json", "{\"x\": 1}\n", error)) << error;
    EXPECT_EQ(folder.read("sub/new.json", error), "{\"x\": 1}\n");
    auto graphs = folder.list_graphs();
    EXPECT_NE(std::find(graphs.begin(), graphs.end(), "sub/b.json"), graphs.end());
}

TEST_F(GraphFolderTest, RefusesDotDotAbsolutePathsAndLinksThatLeadOut) {
    GraphFolder folder(base / "work");
    for (const std::string& path : std::vector<std::string>{"../secret.json", "sub/../../secret.json", "..", "/etc/passwd",
                                   (base / "secret.json").string(), "link.json", "", "a\\..\\..\\secret.json"}) {
        std::string error;
        EXPECT_FALSE(folder.read(path, error)) << path;
        EXPECT_FALSE(error.empty()) << path;
        EXPECT_FALSE(folder.write(path, "{}", error)) << path;
    }
    std::string error;
    folder.read("../secret.json", error);
    EXPECT_NE(error.find("'..' is refused"), std::string::npos) << error;
    folder.read("/etc/passwd", error);
    EXPECT_NE(error.find("absolute paths are refused"), std::string::npos) << error;
    std::ifstream secret(base / "secret.json");
    std::string text((std::istreambuf_iterator<char>(secret)), {});
    EXPECT_EQ(text, "{\"secret\": 1}");
}

// The list names graphs as they are named in the folder, and leaves out what the studio would
// refuse to open: a link to a graph outside.
TEST_F(GraphFolderTest, ListsLinksByTheirOwnNameAndNotThoseThatLeadOut) {
    fs::create_symlink(base / "work" / "sub" / "b.json", base / "work" / "alias.json");
    auto graphs = GraphFolder(base / "work").list_graphs();
    EXPECT_EQ(graphs, (std::vector<std::string>{"a.json", "alias.json", "sub/b.json"}));
}

TEST_F(GraphFolderTest, SavesOnlyGraphs) {
    GraphFolder folder(base / "work");
    std::string error;
    EXPECT_FALSE(folder.write("script.sh", "rm -rf /", error));
    EXPECT_NE(error.find(".json"), std::string::npos);
}

}  // namespace fg::studio
