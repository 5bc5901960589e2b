// The pipeline cache on disk, against the real driver: written when a context ends, given back to
// the next one, and any file that is not this device's whole cache ignored, never a crash.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "scratch_dir.h"
#include "test_shaders.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"
#include "vk/descriptors.h"
#include "vk/pipeline_cache_file.h"
#include "vk_test_support.h"

namespace fg::vk {
namespace {

using test::ScopedEnv;

class PipelineCacheFileTest : public ::testing::Test {
protected:
    std::filesystem::path file() const { return folder_ / "pipelines.bin"; }

    // A context on the cache file that builds one pipeline, then ends (and saves the cache).
    VkPhysicalDeviceProperties build_a_pipeline() {
        ContextOptions options = test::validated_options();
        options.pipeline_cache_file = file();
        Context ctx(options);
        DescriptorSetLayout layout(ctx, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
        ComputePipeline fill(ctx, test::shaders::fill_spv, {layout.handle()}, 12);
        EXPECT_EQ(ctx.validation_errors(), 0u) << test::joined(ctx.validation_messages());
        return ctx.properties();
    }

    std::vector<std::byte> file_bytes() const {
        std::ifstream in(file(), std::ios::binary);
        std::vector<char> chars((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::vector<std::byte> bytes(chars.size());
        std::memcpy(bytes.data(), chars.data(), chars.size());
        return bytes;
    }

    void write_file(const std::vector<std::byte>& bytes) const {
        std::ofstream(file(), std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                      static_cast<std::streamsize>(bytes.size()));
    }

    fg::test::ScratchDir scratch_{"fg_pipeline_cache"};
    const std::filesystem::path& folder_ = scratch_.path();
};

TEST_F(PipelineCacheFileTest, AContextSavesItsCacheForTheDeviceAndTheNextOneReadsIt) {
    const VkPhysicalDeviceProperties device = build_a_pipeline();
    ASSERT_TRUE(std::filesystem::exists(file()));
    EXPECT_TRUE(pipeline_cache_fits(file_bytes(), device));
    EXPECT_EQ(read_pipeline_cache(file(), device), file_bytes());
    build_a_pipeline();
    EXPECT_TRUE(pipeline_cache_fits(file_bytes(), device));
    // Renamed into place: no temporary file is left beside it.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder_), std::filesystem::directory_iterator()), 1);
}

TEST_F(PipelineCacheFileTest, AHeaderOfAnotherDeviceOrVersionDoesNotFit) {
    const VkPhysicalDeviceProperties device = build_a_pipeline();
    const std::vector<std::byte> good = file_bytes();
    ASSERT_TRUE(pipeline_cache_fits(good, device));
    auto changed = [&](std::size_t offset) {
        std::vector<std::byte> bytes = good;
        bytes[offset] ^= std::byte{0x5a};
        return bytes;
    };
    EXPECT_FALSE(pipeline_cache_fits(changed(offsetof(VkPipelineCacheHeaderVersionOne, headerVersion)), device));
    EXPECT_FALSE(pipeline_cache_fits(changed(offsetof(VkPipelineCacheHeaderVersionOne, vendorID)), device));
    EXPECT_FALSE(pipeline_cache_fits(changed(offsetof(VkPipelineCacheHeaderVersionOne, deviceID)), device));
    EXPECT_FALSE(pipeline_cache_fits(changed(offsetof(VkPipelineCacheHeaderVersionOne, pipelineCacheUUID) + 7), device));
    EXPECT_FALSE(pipeline_cache_fits(changed(offsetof(VkPipelineCacheHeaderVersionOne, headerSize) + 2), device));
    EXPECT_FALSE(pipeline_cache_fits(std::span(good).first(sizeof(VkPipelineCacheHeaderVersionOne) - 1), device));
    EXPECT_FALSE(pipeline_cache_fits({}, device));
}

TEST_F(PipelineCacheFileTest, ACorruptOrForeignFileIsIgnoredAndReplaced) {
    const VkPhysicalDeviceProperties device = build_a_pipeline();
    std::vector<std::byte> foreign = file_bytes();
    foreign[offsetof(VkPipelineCacheHeaderVersionOne, deviceID)] ^= std::byte{1};
    std::vector<std::byte> garbage(4096);
    for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = std::byte(i * 131 % 251);
    std::vector<std::byte> damaged = file_bytes();   // this device's header, then bytes that mean nothing
    damaged.resize(damaged.size() + 64, std::byte{0xff});
    for (const auto& bytes : {foreign, garbage, damaged, std::vector<std::byte>{}}) {
        write_file(bytes);
        EXPECT_NO_THROW(build_a_pipeline());
        EXPECT_TRUE(pipeline_cache_fits(file_bytes(), device));
    }
}

TEST_F(PipelineCacheFileTest, AFolderThatCannotBeWrittenCostsNoError) {
    std::ofstream(folder_ / "not_a_folder") << "a file where the cache's folder would be";
    ContextOptions options = test::validated_options();
    options.pipeline_cache_file = folder_ / "not_a_folder" / "pipelines.bin";
    EXPECT_NO_THROW({ Context ctx(options); });
    EXPECT_FALSE(write_pipeline_cache(options.pipeline_cache_file, std::vector<std::byte>(64)));
}

TEST(UserPipelineCacheFile, ComesFromTheEnvironmentOrTheXdgCacheFolder) {
    ScopedEnv home("HOME", "/home/someone");
    {
        ScopedEnv folder("FG_PIPELINE_CACHE", "/tmp/elsewhere");
        EXPECT_EQ(user_pipeline_cache_file(), "/tmp/elsewhere/pipelines.bin");
    }
    {
        ScopedEnv folder("FG_PIPELINE_CACHE", "off");
        EXPECT_TRUE(user_pipeline_cache_file().empty());
    }
    ScopedEnv folder("FG_PIPELINE_CACHE", std::nullopt);
    {
        ScopedEnv xdg("XDG_CACHE_HOME", "/var/cache/someone");
        EXPECT_EQ(user_pipeline_cache_file(), "/var/cache/someone/fractograph/pipelines.bin");
    }
    ScopedEnv xdg("XDG_CACHE_HOME", std::nullopt);
    EXPECT_EQ(user_pipeline_cache_file(), "/home/someone/.cache/fractograph/pipelines.bin");
    ScopedEnv no_home("HOME", std::nullopt);
    EXPECT_TRUE(user_pipeline_cache_file().empty());
}

}  // namespace
}  // namespace fg::vk
