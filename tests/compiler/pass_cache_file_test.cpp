// Passes kept on disk between processes: a later compile reads every pass it compiled before and
// gives the pack compiled without a cache, byte for byte; a damaged file is never trusted.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>

#include "scratch_dir.h"
#include "spirv/pass_cache_file.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;

std::string mandelbulb() { return fg::test::read_source_file("graphs/gallery/mandelbulb.json"); }

std::optional<fg::CompileResult> compile(const std::string& text, fg::PassCache* cache) {
    fg::CompileOptions options;
    options.cache = cache;
    fg::Diagnostics diag;
    auto result = fg::compile_graph(text, fg::NodeLibrary::builtin(), options, diag);
    EXPECT_TRUE(result) << diag.format();
    EXPECT_FALSE(diag.has_errors()) << diag.format();
    return result;
}

std::vector<fs::path> files_in(const fs::path& folder) {
    std::vector<fs::path> files;
    if (fs::exists(folder))
        for (const auto& e : fs::directory_iterator(folder)) files.push_back(e.path());
    return files;
}

// Each test its own folder, empty at first, where no pass exists yet.
class PassCacheFile : public ::testing::Test {
protected:
    fg::test::ScratchDir scratch_{"fg_pass_cache"};
    const fs::path folder_ = scratch_ / "passes";
};

}  // namespace

TEST_F(PassCacheFile, a_new_process_reads_every_pass_from_disk_and_gives_the_same_pack) {
    fg::PassCache first(64, folder_);
    auto compiled = compile(mandelbulb(), &first);
    ASSERT_TRUE(compiled);
    EXPECT_EQ(compiled->times.passes_compiled, compiled->passes.size());
    EXPECT_EQ(files_in(folder_).size(), compiled->passes.size());

    fg::PassCache second(64, folder_);   // what a later fgc starts with
    auto read = compile(mandelbulb(), &second);
    ASSERT_TRUE(read);
    EXPECT_EQ(read->times.passes_compiled, 0u);
    EXPECT_EQ(fg::pack_bytes(*read), fg::pack_bytes(*compile(mandelbulb(), nullptr)));
}

TEST_F(PassCacheFile, a_colour_edit_recompiles_only_the_passes_whose_code_it_changed) {
    fg::PassCache first(64, folder_);
    auto original = compile(fg::test::mandelbulb_with_tone(0.6), &first);
    ASSERT_TRUE(original);
    const auto before = files_in(folder_);

    fg::PassCache second(64, folder_);
    auto edited = compile(fg::test::mandelbulb_with_tone(0.7), &second);
    ASSERT_TRUE(edited);
    // The colour is evaluated where the surface is shaded and where its albedo is written out.
    std::set<std::string> changed;
    for (std::size_t i = 0; i < edited->passes.size(); ++i)
        if (edited->passes[i].source.glsl != original->passes[i].source.glsl) changed.insert(edited->passes[i].source.name);
    EXPECT_EQ(changed, (std::set<std::string>{"aov", "shade"}));
    EXPECT_EQ(edited->times.passes_compiled, changed.size());
    EXPECT_EQ(files_in(folder_).size(), before.size() + changed.size());
    EXPECT_EQ(fg::pack_bytes(*edited), fg::pack_bytes(*compile(fg::test::mandelbulb_with_tone(0.7), nullptr)));
}

TEST_F(PassCacheFile, a_damaged_file_is_ignored_and_written_again) {
    fg::PassCache first(64, folder_);
    ASSERT_TRUE(compile(mandelbulb(), &first));
    auto files = files_in(folder_);
    ASSERT_GE(files.size(), 3u);
    {   // one byte of SPIR-V flipped
        std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(100);
        char c = static_cast<char>(f.get());
        f.seekp(100);
        f.put(static_cast<char>(~c));
    }
    fs::resize_file(files[1], fs::file_size(files[1]) / 2);   // cut short
    fs::copy_file(files[3 % files.size()], files[2], fs::copy_options::overwrite_existing);   // another pass's file

    fg::PassCache second(64, folder_);
    auto repaired = compile(mandelbulb(), &second);
    ASSERT_TRUE(repaired);
    EXPECT_EQ(repaired->times.passes_compiled, 3u);
    EXPECT_EQ(fg::pack_bytes(*repaired), fg::pack_bytes(*compile(mandelbulb(), nullptr)));

    fg::PassCache third(64, folder_);
    auto read = compile(mandelbulb(), &third);
    ASSERT_TRUE(read);
    EXPECT_EQ(read->times.passes_compiled, 0u);
}

TEST_F(PassCacheFile, the_environment_names_the_folder_and_off_writes_nothing) {
    const std::string home = (scratch_ / "home").string();
    ::setenv("XDG_CACHE_HOME", home.c_str(), 1);
    ::unsetenv("FG_PASS_CACHE");
    EXPECT_EQ(fg::user_pass_cache_folder(), fs::path(home) / "fractograph" / "passes");
    ::setenv("FG_PASS_CACHE", (folder_ / "mine").c_str(), 1);
    EXPECT_EQ(fg::user_pass_cache_folder(), folder_ / "mine");

    ::setenv("FG_PASS_CACHE", "off", 1);
    EXPECT_EQ(fg::user_pass_cache_folder(), fs::path());
    fg::PassCache off(64, fg::user_pass_cache_folder());
    ASSERT_TRUE(compile(mandelbulb(), &off));
    EXPECT_TRUE(files_in(scratch_.path()).empty());
    ::unsetenv("XDG_CACHE_HOME");
}

TEST_F(PassCacheFile, a_folder_that_cannot_be_written_compiles_all_the_same) {
    std::ofstream(scratch_ / "a_file") << "not a folder";
    fg::PassCache cache(64, scratch_ / "a_file" / "passes");   // even root cannot make this folder
    auto compiled = compile(mandelbulb(), &cache);
    ASSERT_TRUE(compiled);
    EXPECT_EQ(fg::pack_bytes(*compiled), fg::pack_bytes(*compile(mandelbulb(), nullptr)));
    EXPECT_EQ(files_in(scratch_.path()).size(), 1u);
}

TEST_F(PassCacheFile, the_files_used_longest_ago_go_first_when_the_folder_is_full) {
    const std::vector<std::uint32_t> spirv(1000, 7);
    const auto now = fs::file_time_type::clock::now();
    for (std::uint64_t key = 1; key <= 3; ++key) {
        ASSERT_TRUE(fg::write_pass_file(fg::pass_file(folder_, key), key, spirv));
        fs::last_write_time(fg::pass_file(folder_, key), now - std::chrono::hours(10 - key));
    }
    fg::trim_pass_folder(folder_, 2 * fs::file_size(fg::pass_file(folder_, 1)));
    EXPECT_FALSE(fs::exists(fg::pass_file(folder_, 1)));
    EXPECT_EQ(fg::read_pass_file(fg::pass_file(folder_, 2), 2), spirv);
    EXPECT_EQ(fg::read_pass_file(fg::pass_file(folder_, 3), 3), spirv);
    EXPECT_FALSE(fg::read_pass_file(fg::pass_file(folder_, 3), 2));   // a file under another key's name
}
