#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_shaders.h"
#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/compute_pipeline.h"
#include "vk/descriptors.h"
#include "vk/vulkan_error.h"
#include "vk_test_support.h"

namespace fg::vk {
namespace {

using ComputeTest = test::VulkanTest;

struct FillPush {
    std::uint32_t count;
    std::uint32_t scale;
    std::uint32_t offset;
};

constexpr std::uint32_t kSentinel = 0xDEADBEEF;

// A set with one storage buffer at binding 0, the shape most test shaders use.
struct OneBufferSet {
    OneBufferSet(const Context& ctx, const Buffer& buffer)
        : layout(ctx, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}), pool(ctx, layout, 1), set(pool.allocate(layout)) {
        write_storage_buffer(ctx, set, 0, buffer);
    }
    DescriptorSetLayout layout;
    DescriptorPool pool;
    VkDescriptorSet set;
};

// "" when `actual` matches `expected`, else a description of the first difference.
template <class T>
std::string first_difference(const std::vector<T>& actual, const std::vector<T>& expected) {
    if (actual.size() != expected.size()) return "sizes differ";
    const auto [a, e] = std::mismatch(actual.begin(), actual.end(), expected.begin());
    if (a == actual.end()) return "";
    return "element " + std::to_string(a - actual.begin()) + " is " + std::to_string(*a) + ", expected " +
           std::to_string(*e);
}

TEST_F(ComputeTest, AComputeDispatchWritesEveryElementOfAStorageBuffer) {
    constexpr std::uint32_t count = 1000;  // not a multiple of the workgroup size
    constexpr std::uint32_t tail = 24;     // past `count`: must stay untouched
    Buffer values(ctx(), (count + tail) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::Readback);
    values.upload(std::vector<std::uint32_t>(count + tail, kSentinel));
    OneBufferSet binding(ctx(), values);
    ComputePipeline fill(ctx(), test::shaders::fill_spv, {binding.layout.handle()}, sizeof(FillPush));

    const FillPush push{count, 3, 7};
    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        fill.dispatch(cmd, binding.set, {groups_for(count, 64)}, bytes_of(push));
        compute_to_host_barrier(cmd);
    });

    std::vector<std::uint32_t> expected(count + tail, kSentinel);
    for (std::uint32_t i = 0; i < count; ++i) expected[i] = i * 3 + 7;
    EXPECT_EQ(first_difference(values.download_as<std::uint32_t>(count + tail), expected), "");
}

TEST_F(ComputeTest, DeviceLocalResultsAreReadBackThroughStaging) {
    constexpr std::uint32_t count = 64 * 100;
    Buffer values(ctx(), count * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
    values.upload(std::vector<std::uint32_t>(count, kSentinel));
    OneBufferSet binding(ctx(), values);
    ComputePipeline fill(ctx(), test::shaders::fill_spv, {binding.layout.handle()}, sizeof(FillPush));

    const FillPush push{count, 1, 100};
    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        // The upload happened in an earlier submission; its copy must land before the shader.
        transfer_to_compute_barrier(cmd);
        fill.dispatch(cmd, binding.set, {groups_for(count, 64)}, bytes_of(push));
    });

    std::vector<std::uint32_t> expected(count);
    for (std::uint32_t i = 0; i < count; ++i) expected[i] = i + 100;
    EXPECT_EQ(first_difference(values.download_as<std::uint32_t>(count), expected), "");
}

// Checks the values only: lavapipe runs dispatches in order and layer 1.3.239 does not report
// dispatch -> dispatch hazards, so on this machine the barrier itself is not proven necessary.
TEST_F(ComputeTest, ASecondDispatchBehindABarrierReadsTheFirstOnesResults) {
    constexpr std::uint32_t count = 64 * 16;
    Buffer values(ctx(), count * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::Readback);
    OneBufferSet binding(ctx(), values);
    ComputePipeline fill(ctx(), test::shaders::fill_spv, {binding.layout.handle()}, sizeof(FillPush));
    ComputePipeline twice(ctx(), test::shaders::double_values_spv, {binding.layout.handle()}, 4);

    const FillPush push{count, 5, 1};
    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        fill.dispatch(cmd, binding.set, {groups_for(count, 64)}, bytes_of(push));
        compute_to_compute_barrier(cmd);
        twice.dispatch(cmd, binding.set, {groups_for(count, 64)}, bytes_of(count));
        compute_to_host_barrier(cmd);
    });

    std::vector<std::uint32_t> expected(count);
    for (std::uint32_t i = 0; i < count; ++i) expected[i] = (i * 5 + 1) * 2;
    EXPECT_EQ(first_difference(values.download_as<std::uint32_t>(count), expected), "");
}

TEST_F(ComputeTest, ACopyOfADispatchsOutputSeesItAfterABarrier) {
    constexpr std::uint32_t count = 64 * 4;
    Buffer values(ctx(), count * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
    Buffer readback(ctx(), count * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::Readback);
    OneBufferSet binding(ctx(), values);
    ComputePipeline fill(ctx(), test::shaders::fill_spv, {binding.layout.handle()}, sizeof(FillPush));

    const FillPush push{count, 1, 9};
    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        fill.dispatch(cmd, binding.set, {groups_for(count, 64)}, bytes_of(push));
        compute_to_transfer_barrier(cmd);
        const VkBufferCopy region{0, 0, count * 4};
        vkCmdCopyBuffer(cmd, values.handle(), readback.handle(), 1, &region);
        transfer_to_host_barrier(cmd);
    });

    std::vector<std::uint32_t> expected(count);
    for (std::uint32_t i = 0; i < count; ++i) expected[i] = i + 9;
    EXPECT_EQ(first_difference(readback.download_as<std::uint32_t>(count), expected), "");
}

// Proves the fixture's synchronization validation bites, so the barrier tests above mean
// something. (Layer 1.3.239 tracks dispatch -> copy hazards but not dispatch -> dispatch ones.)
TEST_F(ComputeTest, ACopyOfADispatchsOutputWithoutABarrierIsReportedAsAHazard) {
    expect_validation_errors();
    constexpr std::uint32_t count = 64;
    Buffer values(ctx(), count * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
    Buffer readback(ctx(), count * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::Readback);
    OneBufferSet binding(ctx(), values);
    ComputePipeline fill(ctx(), test::shaders::fill_spv, {binding.layout.handle()}, sizeof(FillPush));

    const FillPush push{count, 1, 0};
    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        fill.dispatch(cmd, binding.set, {1}, bytes_of(push));
        const VkBufferCopy region{0, 0, count * 4};
        vkCmdCopyBuffer(cmd, values.handle(), readback.handle(), 1, &region);  // no barrier
        transfer_to_host_barrier(cmd);
    });
    const auto& messages = ctx().validation_messages();
    EXPECT_TRUE(std::any_of(messages.begin(), messages.end(),
                            [](const std::string& m) { return m.find("SYNC-HAZARD-READ-AFTER-WRITE") != std::string::npos; }))
        << test::joined(messages);
}

TEST_F(ComputeTest, ASpecializationConstantChangesWhatTheShaderComputes) {
    constexpr std::uint32_t count = 64;
    Buffer plain_out(ctx(), count * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::Readback);
    Buffer special_out(ctx(), count * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::Readback);
    OneBufferSet plain_set(ctx(), plain_out);
    OneBufferSet special_set(ctx(), special_out);

    ComputePipeline plain(ctx(), test::shaders::specialized_spv, {plain_set.layout.handle()});
    const SpecializationValues values{{0, 3u}, {1, -5}, {2, 0.5f}};
    ComputePipeline special(ctx(), test::shaders::specialized_spv, {special_set.layout.handle()}, 0, values);

    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        plain.dispatch(cmd, plain_set.set, {1});
        special.dispatch(cmd, special_set.set, {1});
        compute_to_host_barrier(cmd);
    });

    const auto plain_values = plain_out.download_as<float>(count);
    const auto special_values = special_out.download_as<float>(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        EXPECT_EQ(plain_values[i], static_cast<float>(i)) << i;
        EXPECT_EQ(special_values[i], (3.0f * static_cast<float>(i) - 5.0f) * 0.5f) << i;
    }
}

TEST_F(ComputeTest, SpecializationValuesReplaceByIdAndRefuseDuplicates) {
    SpecializationValues values;
    values.set(4, 1u).set(4, 2.5f).set(7, -1);
    ASSERT_EQ(values.values.size(), 2u);
    EXPECT_EQ(std::get<float>(values.values[0].value), 2.5f);
    EXPECT_EQ(std::get<std::int32_t>(values.values[1].value), -1);
    EXPECT_THROW((SpecializationValues{{1, 1u}, {1, 2u}}), std::invalid_argument);
}

TEST_F(ComputeTest, AShaderReadsAUniformBufferAndADeviceLocalInput) {
    constexpr std::uint32_t count = 300;
    struct Params {
        float factor;
        float bias;
    };
    const Params params{2.5f, 1.0f};
    Buffer uniforms(ctx(), sizeof(Params), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryKind::HostVisible);
    uniforms.upload(std::as_bytes(std::span(&params, 1)));
    Buffer inputs(ctx(), count * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
    std::vector<float> input_values(count);
    for (std::uint32_t i = 0; i < count; ++i) input_values[i] = static_cast<float>(i) * 0.25f;
    inputs.upload(input_values);
    Buffer outputs(ctx(), count * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::Readback);

    DescriptorSetLayout layout(ctx(), {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                       {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                       {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    DescriptorPool pool(ctx(), layout, 1);
    const VkDescriptorSet set = pool.allocate(layout);
    write_uniform_buffer(ctx(), set, 0, uniforms);
    write_storage_buffer(ctx(), set, 1, inputs);
    write_storage_buffer(ctx(), set, 2, outputs);
    ComputePipeline pipeline(ctx(), test::shaders::scale_by_uniform_spv, {layout.handle()}, 4);

    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        pipeline.dispatch(cmd, set, {groups_for(count, 64)}, bytes_of(count));
        compute_to_host_barrier(cmd);
    });
    const auto result = outputs.download_as<float>(count);
    for (std::uint32_t i = 0; i < count; ++i) EXPECT_FLOAT_EQ(result[i], input_values[i] * 2.5f + 1.0f) << i;
}

TEST_F(ComputeTest, APushConstantBlockLargerThanTheDeviceLimitIsRefused) {
    DescriptorSetLayout layout(ctx(), {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    const std::uint32_t limit = ctx().limits().maxPushConstantsSize;
    try {
        ComputePipeline pipeline(ctx(), test::shaders::fill_spv, {layout.handle()}, limit + 4);
        FAIL() << "a " << limit + 4 << "-byte push-constant block was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("limit of " + std::to_string(limit) + " bytes"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(ComputePipeline(ctx(), test::shaders::fill_spv, {layout.handle()}, 10), std::invalid_argument);
    EXPECT_NO_THROW(ComputePipeline(ctx(), test::shaders::fill_spv, {layout.handle()}, limit));
}

TEST_F(ComputeTest, MorePushConstantBytesThanDeclaredAreRefused) {
    Buffer values(ctx(), 64 * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::Readback);
    OneBufferSet binding(ctx(), values);
    ComputePipeline twice(ctx(), test::shaders::double_values_spv, {binding.layout.handle()}, 4);
    OneShot shot(ctx());
    const FillPush too_big{1, 2, 3};
    EXPECT_THROW(twice.dispatch(shot.cmd(), binding.set, {1}, bytes_of(too_big)), std::invalid_argument);
}

TEST_F(ComputeTest, WordsThatAreNotSpirvAreRefused) {
    DescriptorSetLayout layout(ctx(), {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    const std::vector<std::uint32_t> not_spirv{0x12345678, 0, 0, 0, 0};
    EXPECT_THROW(ComputePipeline(ctx(), not_spirv, {layout.handle()}), std::invalid_argument);
    EXPECT_THROW(ComputePipeline(ctx(), std::span<const std::uint32_t>{}, {layout.handle()}), std::invalid_argument);
}

TEST_F(ComputeTest, ADescriptorBindingListedTwiceIsRefused) {
    EXPECT_THROW(DescriptorSetLayout(ctx(), {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                             {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}}),
                 std::invalid_argument);
}

TEST(DescriptorPoolSizes, CountEachDescriptorTypeOverEverySet) {
    const std::vector<DescriptorBinding> bindings{{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                                  {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                  {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT, 3},
                                                  {3, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
    const auto sizes = pool_sizes(bindings, 5);
    ASSERT_EQ(sizes.size(), 3u);
    for (const VkDescriptorPoolSize& size : sizes) {
        if (size.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) EXPECT_EQ(size.descriptorCount, 5u);
        else if (size.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER) EXPECT_EQ(size.descriptorCount, 20u);
        else if (size.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE) EXPECT_EQ(size.descriptorCount, 5u);
        else ADD_FAILURE() << "unexpected descriptor type " << size.type;
    }
}

TEST_F(ComputeTest, ADescriptorPoolHandsOutSetsAgainAfterAReset) {
    DescriptorSetLayout layout(ctx(), {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    DescriptorPool pool(ctx(), layout, 2);
    EXPECT_NE(pool.allocate(layout), VK_NULL_HANDLE);
    EXPECT_NE(pool.allocate(layout), VK_NULL_HANDLE);
    pool.reset();
    EXPECT_NE(pool.allocate(layout), VK_NULL_HANDLE);
    EXPECT_NE(pool.allocate(layout), VK_NULL_HANDLE);
}

TEST(GroupCount, CoversEveryItemWithWholeWorkgroups) {
    EXPECT_EQ(groups_for(0, 64), 0u);
    EXPECT_EQ(groups_for(1, 64), 1u);
    EXPECT_EQ(groups_for(64, 64), 1u);
    EXPECT_EQ(groups_for(65, 64), 2u);
    EXPECT_EQ(groups_for(1000, 64), 16u);
}

}  // namespace
}  // namespace fg::vk
