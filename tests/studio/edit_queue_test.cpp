#include <gtest/gtest.h>

#include <atomic>

#include "studio/edit_queue.h"

namespace fg::studio {

TEST(EditQueue, AFloodOfEditsCompilesOnlyAFewAndTheLatestWins) {
    std::atomic<int> compiles{0};
    std::string last;
    EditQueue queue([&](const std::string& text, std::uint64_t) {
        ++compiles;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        last = text;
        return EditOutcome{0, true, nlohmann::json::array(), 20.0, 0.0};
    });
    std::uint64_t revision = 0;
    for (int i = 0; i < 200; ++i) revision = queue.submit("edit " + std::to_string(i));
    EXPECT_EQ(revision, 200u);
    EditOutcome outcome = queue.wait_for(revision, std::chrono::seconds(10));
    EXPECT_EQ(outcome.revision, 200u);
    EXPECT_EQ(last, "edit 199");
    EXPECT_LE(compiles.load(), 3);
    EXPECT_EQ(queue.skipped() + static_cast<std::uint64_t>(compiles.load()), 200u);
}

TEST(EditQueue, ACompileThatThrowsBecomesADiagnostic) {
    EditQueue queue([](const std::string&, std::uint64_t) -> EditOutcome { throw std::runtime_error("pipelines failed"); });
    EditOutcome outcome = queue.wait_for(queue.submit("x"), std::chrono::seconds(10));
    EXPECT_FALSE(outcome.ok);
    EXPECT_EQ(outcome.diagnostics[0]["message"], "pipelines failed");
}

}  // namespace fg::studio
