#include <algorithm>
#include <cctype>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "test_shaders.h"
#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"
#include "vk/descriptors.h"
#include "vk/vulkan_error.h"
#include "vk_test_support.h"

namespace fg::vk {
namespace {

using test::ScopedEnv;
using test::VulkanTest;

bool any_message_contains(const std::vector<std::string>& messages, std::string_view text) {
    return std::any_of(messages.begin(), messages.end(),
                       [&](const std::string& m) { return m.find(text) != std::string::npos; });
}

std::string context_error(const ContextOptions& options) {
    try {
        Context ctx(options);
    } catch (const VulkanError& e) {
        return e.what();
    }
    return "(no error)";
}

using ContextTest = VulkanTest;

TEST_F(ContextTest, TheChosenDeviceCanRunComputeAndTimeIt) {
    EXPECT_FALSE(ctx().device_name().empty());
    EXPECT_EQ(ctx().device_name(), std::string(ctx().properties().deviceName));
    EXPECT_GE(ctx().properties().apiVersion, VK_API_VERSION_1_3);
    EXPECT_NE(ctx().instance(), VK_NULL_HANDLE);
    EXPECT_NE(ctx().physical(), VK_NULL_HANDLE);
    EXPECT_NE(ctx().device(), VK_NULL_HANDLE);
    EXPECT_NE(ctx().queue(), VK_NULL_HANDLE);
    EXPECT_NE(ctx().pipeline_cache(), VK_NULL_HANDLE);

    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx().physical(), &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx().physical(), &count, families.data());
    ASSERT_LT(ctx().queue_family(), count);
    EXPECT_TRUE(families[ctx().queue_family()].queueFlags & VK_QUEUE_COMPUTE_BIT);

    // require_timestamps is on by default, so the context must be able to time passes.
    EXPECT_TRUE(ctx().timestamps_supported());
    EXPECT_GT(ctx().timestamp_period_ns(), 0.0f);
    EXPECT_GT(ctx().timestamp_valid_bits(), 0u);
    EXPECT_EQ(ctx().is_cpu_device(), ctx().properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU);
}

TEST_F(ContextTest, ADeviceCanBeChosenByIndexOrByPartOfItsNameInAnyCase) {
    const std::string name = ctx().device_name();

    ContextOptions by_index = test::validated_options();
    by_index.device = "0";
    Context first(by_index);
    EXPECT_FALSE(first.device_name().empty());

    // A middle slice of the automatic choice's name, upper-cased, finds it again.
    std::string part = name.substr(name.size() / 4, std::max<std::size_t>(1, name.size() / 2));
    std::transform(part.begin(), part.end(), part.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    ContextOptions by_name = test::validated_options();
    by_name.device = part;
    Context named(by_name);
    EXPECT_EQ(named.device_name(), name);
    EXPECT_EQ(first.validation_errors() + named.validation_errors(), 0u);
}

TEST_F(ContextTest, ChoosingADeviceThatDoesNotExistListsTheAvailableDevices) {
    ContextOptions options = test::validated_options();
    options.device = "no-such-gpu";
    const std::string message = context_error(options);
    EXPECT_NE(message.find("no Vulkan device matches 'no-such-gpu'"), std::string::npos) << message;
    EXPECT_NE(message.find("available devices:"), std::string::npos) << message;
    EXPECT_NE(message.find(ctx().device_name()), std::string::npos) << message;

    options.device = "99";
    const std::string by_index = context_error(options);
    EXPECT_NE(by_index.find("no Vulkan device matches '99'"), std::string::npos) << by_index;
    EXPECT_NE(by_index.find(ctx().device_name()), std::string::npos) << by_index;
}

TEST_F(ContextTest, ValidationErrorsAreCounted) {
    expect_validation_errors();
    ASSERT_EQ(ctx().validation_errors(), 0u) << test::joined(ctx().validation_messages());

    // A zero-sized buffer breaks VUID-VkBufferCreateInfo-size-00912.
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 0;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    vkCreateBuffer(ctx().device(), &info, nullptr, &buffer);
    if (buffer) vkDestroyBuffer(ctx().device(), buffer, nullptr);

    EXPECT_GT(ctx().validation_errors(), 0u);
    EXPECT_TRUE(any_message_contains(ctx().validation_messages(), "VUID-VkBufferCreateInfo-size-00912"))
        << test::joined(ctx().validation_messages());
}

TEST_F(ContextTest, ObjectsLeftAliveWhenTheContextEndsAreReported) {
    expect_validation_errors();
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 256;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    VkBuffer leaked = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateBuffer(ctx().device(), &info, nullptr, &leaked), VK_SUCCESS);
    ASSERT_EQ(ctx().validation_errors(), 0u) << test::joined(ctx().validation_messages());

    // The leak is only noticed inside vkDestroyDevice: the messenger must still be listening.
    const auto log = finish_context();
    EXPECT_GT(log->errors(), 0u);
    EXPECT_TRUE(any_message_contains(log->messages(), "VkBuffer")) << test::joined(log->messages());
}

TEST_F(ContextTest, DoublePrecisionIsOffUnlessAskedFor) {
    expect_validation_errors();
    EXPECT_FALSE(ctx().shader_float64_enabled());
    EXPECT_FALSE(ctx().shader_int64_enabled());
    DescriptorSetLayout layout(ctx(), {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    try {
        ComputePipeline pipeline(ctx(), test::shaders::float64_spv, {layout.handle()});
    } catch (const VulkanError&) {
        // Some drivers refuse it outright; the validation message below is what matters.
    }
    EXPECT_GT(ctx().validation_errors(), 0u);
    EXPECT_TRUE(any_message_contains(ctx().validation_messages(), "Float64"))
        << test::joined(ctx().validation_messages());
}

TEST_F(ContextTest, DoublePrecisionShadersRunWhenAskedFor) {
    ContextOptions options = test::validated_options();
    options.shader_float64 = true;
    Context ctx64(options);
    {
        VkPhysicalDeviceFeatures supported{};
        vkGetPhysicalDeviceFeatures(ctx64.physical(), &supported);
        if (!supported.shaderFloat64) GTEST_SKIP() << ctx64.device_name() << " has no shaderFloat64";
        ASSERT_TRUE(ctx64.shader_float64_enabled());

        constexpr std::uint32_t count = 64;
        Buffer values(ctx64, count * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::Readback);
        DescriptorSetLayout layout(ctx64, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
        DescriptorPool pool(ctx64, layout, 1);
        const VkDescriptorSet set = pool.allocate(layout);
        write_storage_buffer(ctx64, set, 0, values);
        ComputePipeline pipeline(ctx64, test::shaders::float64_spv, {layout.handle()});
        OneShot::run(ctx64, [&](VkCommandBuffer cmd) {
            pipeline.dispatch(cmd, set, {1});
            compute_to_host_barrier(cmd);
        });
        const auto result = values.download_as<float>(count);
        for (std::uint32_t i = 0; i < count; ++i) EXPECT_FLOAT_EQ(result[i], static_cast<float>(i)) << i;
    }
    EXPECT_EQ(ctx64.validation_errors(), 0u) << test::joined(ctx64.validation_messages());
}

TEST(ContextEnvironment, ValidationCanBeForcedOnFromTheEnvironment) {
    {
        ScopedEnv off("FG_VK_VALIDATION", std::nullopt);
        Context ctx;
        EXPECT_FALSE(ctx.validation_enabled());
    }
    {
        ScopedEnv on("FG_VK_VALIDATION", "1");
        Context ctx;
        EXPECT_TRUE(ctx.validation_enabled());
        EXPECT_EQ(ctx.validation_errors(), 0u) << test::joined(ctx.validation_messages());
    }
}

TEST(ContextEnvironment, AMissingValidationLayerIsAWarningNotAFailure) {
    // The loader finds explicit layers only on VK_LAYER_PATH when it is set.
    ScopedEnv layer_path("VK_LAYER_PATH", "/nonexistent/fg_no_layers");
    ScopedEnv add_layer_path("VK_ADD_LAYER_PATH", std::nullopt);
    ContextOptions options;
    options.validation = true;
    std::unique_ptr<Context> ctx;
    ASSERT_NO_THROW(ctx = std::make_unique<Context>(options));
    EXPECT_FALSE(ctx->validation_enabled());
}

TEST(ContextEnvironment, AMachineWithoutAVulkanDriverGetsAnInstallHint) {
    // Point the loader at a driver manifest that does not exist (both spellings it reads).
    ScopedEnv icd("VK_ICD_FILENAMES", "/nonexistent/fg_no_driver.json");
    ScopedEnv driver_files("VK_DRIVER_FILES", "/nonexistent/fg_no_driver.json");
    const std::string message = context_error(ContextOptions{});
    EXPECT_NE(message.find("no Vulkan device found: install mesa-vulkan-drivers for lavapipe"), std::string::npos)
        << message;
}

}  // namespace
}  // namespace fg::vk
