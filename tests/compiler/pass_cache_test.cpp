// Passes kept across compiles by their GLSL: an edit recompiles only the passes it changed, and a
// pack built from cached passes is the pack built without them, byte for byte.
#include <gtest/gtest.h>

#include <string>

#include "test_support.h"

namespace {

std::string mandelbulb() { return fg::test::read_source_file("graphs/gallery/mandelbulb.json"); }

std::optional<fg::CompileResult> compile(const std::string& text, const fg::CompileOptions& options) {
    fg::Diagnostics diag;
    auto result = fg::compile_graph(text, fg::NodeLibrary::builtin(), options, diag);
    EXPECT_TRUE(result) << diag.format();
    return result;
}

}  // namespace

TEST(PassCache, a_graph_compiled_again_compiles_no_pass_and_gives_the_same_pack) {
    fg::PassCache cache;
    fg::CompileOptions cached;
    cached.cache = &cache;
    auto plain = compile(mandelbulb(), {});
    auto first = compile(mandelbulb(), cached);
    auto second = compile(mandelbulb(), cached);
    ASSERT_TRUE(plain && first && second);
    EXPECT_EQ(first->times.passes_compiled, first->passes.size());
    EXPECT_EQ(second->times.passes_compiled, 0u);
    EXPECT_EQ(cache.compiles(), first->passes.size());
    EXPECT_EQ(fg::pack_bytes(*first), fg::pack_bytes(*plain));
    EXPECT_EQ(fg::pack_bytes(*second), fg::pack_bytes(*plain));
}

TEST(PassCache, a_colour_edit_recompiles_the_passes_that_shade_and_no_other) {
    fg::PassCache cache;
    fg::CompileOptions cached;
    cached.cache = &cache;
    ASSERT_TRUE(compile(fg::test::mandelbulb_with_tone(0.6), cached));
    auto edited = compile(fg::test::mandelbulb_with_tone(0.7), cached);
    ASSERT_TRUE(edited);
    // The marching passes evaluate the distance only: the trap's colour is not in their code.
    EXPECT_GT(edited->times.passes_compiled, 0u);
    EXPECT_LT(edited->times.passes_compiled, edited->passes.size() / 2);
    EXPECT_EQ(fg::pack_bytes(*edited), fg::pack_bytes(*compile(fg::test::mandelbulb_with_tone(0.7), {})));
}

TEST(PassCache, optimised_and_plain_spirv_of_one_pass_are_kept_apart) {
    fg::PassCache cache;
    fg::CompileOptions plain, optimised;
    plain.optimize = false;
    plain.cache = optimised.cache = &cache;
    ASSERT_TRUE(compile(mandelbulb(), plain));
    auto full = compile(mandelbulb(), optimised);
    ASSERT_TRUE(full);
    EXPECT_EQ(full->times.passes_compiled, full->passes.size());
    EXPECT_EQ(fg::pack_bytes(*full), fg::pack_bytes(*compile(mandelbulb(), {})));
}

TEST(PassCache, a_compile_of_some_passes_gives_a_pack_of_those_alone) {
    fg::CompileOptions options;
    options.only_passes = {"conemarch", "shade"};
    auto r = compile(mandelbulb(), options);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->passes.size(), 2u);
    EXPECT_EQ(r->manifest.passes.size(), 2u);
    EXPECT_NE(r->manifest.find_pass("conemarch"), nullptr);
    EXPECT_NE(r->manifest.find_pass("shade"), nullptr);
}

TEST(PassCache, the_oldest_pass_makes_room_when_it_is_full) {
    fg::PassCache cache(2);
    cache.store(1, {});
    cache.store(2, {});
    cache.store(3, {});
    EXPECT_FALSE(cache.find(1));
    EXPECT_TRUE(cache.find(2));
    EXPECT_TRUE(cache.find(3));
    EXPECT_EQ(cache.compiles(), 3u);
}
