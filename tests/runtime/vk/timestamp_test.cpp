#include <cstdint>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "test_shaders.h"
#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/compute_pipeline.h"
#include "vk/descriptors.h"
#include "vk/timestamp_queries.h"
#include "vk_test_support.h"

namespace fg::vk {
namespace {

// The busy shader with its buffer, enough work that a pass lasts measurably long even on a GPU.
class BusyPass {
public:
    explicit BusyPass(const Context& ctx)
        : values_(ctx, kInvocations * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal),
          layout_(ctx, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}),
          pool_(ctx, layout_, 1),
          set_(pool_.allocate(layout_)),
          pipeline_(ctx, test::shaders::busy_spv, {layout_.handle()}, 4) {
        write_storage_buffer(ctx, set_, 0, values_);
    }

    void record(VkCommandBuffer cmd, std::uint32_t iterations) const {
        // Successive passes write the same buffer.
        compute_to_compute_barrier(cmd);
        pipeline_.dispatch(cmd, set_, {kInvocations / 64}, bytes_of(iterations));
    }

private:
    static constexpr std::uint32_t kInvocations = 64 * 64;
    Buffer values_;
    DescriptorSetLayout layout_;
    DescriptorPool pool_;
    VkDescriptorSet set_;
    ComputePipeline pipeline_;
};

using TimestampTest = test::VulkanTest;

TEST_F(TimestampTest, TimestampsMeasureANonNegativeDurationForALabelledPass) {
    BusyPass busy(ctx());
    GpuTimer timer(ctx());
    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        timer.reset(cmd);
        timer.begin(cmd, "busy");
        busy.record(cmd, 2000);
        timer.end(cmd, "busy");
    });
    const auto results = timer.results();
    ASSERT_EQ(results.size(), 1u);
    ASSERT_TRUE(results.contains("busy"));
    // Some real work was done, and no clock runs backwards (which would wrap to ~2^64 ticks).
    EXPECT_GT(results.at("busy"), 0.0);
    EXPECT_LT(results.at("busy"), 60'000.0);
}

TEST_F(TimestampTest, ALabelTimedSeveralTimesReportsTheSumOfItsPasses) {
    BusyPass busy(ctx());
    GpuTimer timer(ctx());
    if (!ctx().host_query_reset_enabled()) GTEST_SKIP() << "needs hostQueryReset";
    timer.reset();  // on the host this time
    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        timer.begin(cmd, "all");
        timer.begin(cmd, "step");
        busy.record(cmd, 1000);
        timer.end(cmd, "step");
        timer.begin(cmd, "step");
        busy.record(cmd, 1000);
        timer.end(cmd, "step");
        timer.end(cmd, "all");
    });
    const auto results = timer.results();
    ASSERT_EQ(results.size(), 2u);
    // "all" brackets both "step" passes, so their sum fits inside it.
    EXPECT_GT(results.at("step"), 0.0);
    EXPECT_LE(results.at("step"), results.at("all") * 1.0001 + 1e-6);
}

TEST_F(TimestampTest, ATimerCanBeResetAndUsedAgain) {
    BusyPass busy(ctx());
    GpuTimer timer(ctx(), 1);
    for (int round = 0; round < 3; ++round) {
        OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
            timer.reset(cmd);
            timer.begin(cmd, "round");
            busy.record(cmd, 100);
            timer.end(cmd, "round");
        });
        const auto results = timer.results();
        ASSERT_EQ(results.size(), 1u) << round;
        EXPECT_GT(results.at("round"), 0.0) << round;
    }
}

TEST_F(TimestampTest, MisusedPassesAreRefused) {
    GpuTimer timer(ctx(), 2);
    OneShot shot(ctx());
    timer.reset(shot.cmd());
    EXPECT_THROW(timer.end(shot.cmd(), "never begun"), std::logic_error);
    timer.begin(shot.cmd(), "a");
    EXPECT_THROW(timer.begin(shot.cmd(), "a"), std::logic_error);
    EXPECT_THROW(timer.results(), std::logic_error);  // "a" is still open
    // Two passes fit: "a" and "b". A third begin would leave an end with no query.
    timer.begin(shot.cmd(), "b");
    EXPECT_THROW(timer.begin(shot.cmd(), "c"), std::logic_error);
    timer.end(shot.cmd(), "b");
    timer.end(shot.cmd(), "a");
    shot.submit_and_wait();
    EXPECT_EQ(timer.results().size(), 2u);
}

TEST_F(TimestampTest, ResultsOfWorkNotYetSubmittedAreRefusedRatherThanAwaited) {
    if (!ctx().host_query_reset_enabled()) GTEST_SKIP() << "needs hostQueryReset";
    GpuTimer timer(ctx());  // reset on the host at construction
    OneShot shot(ctx());
    timer.begin(shot.cmd(), "pending");
    timer.end(shot.cmd(), "pending");
    EXPECT_THROW(timer.results(), std::logic_error);
    shot.submit_and_wait();
    EXPECT_EQ(timer.results().size(), 1u);
}

TEST(TimestampArithmetic, DurationsWithTheSameLabelAreSummed) {
    const std::vector<TimedInterval> intervals{{"march", 100, 300}, {"shade", 300, 350}, {"march", 1000, 1100}};
    const auto ms = sum_intervals_ms(intervals, 64, 1000.0f);  // 1 tick = 1 us
    ASSERT_EQ(ms.size(), 2u);
    EXPECT_DOUBLE_EQ(ms.at("march"), 0.3);
    EXPECT_DOUBLE_EQ(ms.at("shade"), 0.05);
}

TEST(TimestampArithmetic, OnlyTheValidBitsCountAndACounterWrapIsNotNegative) {
    // 36 valid bits: the counter wraps from 2^36 - 10 to 5, which is 15 ticks later.
    const std::uint64_t wrap = std::uint64_t{1} << 36;
    const std::vector<TimedInterval> wrapped{{"pass", wrap - 10, 5}};
    EXPECT_DOUBLE_EQ(sum_intervals_ms(wrapped, 36, 2.0f).at("pass"), 15 * 2.0 / 1e6);

    // Garbage above the valid bits is ignored.
    const std::vector<TimedInterval> noisy{{"pass", 0xFFFF'0000'0000'0010ull, 0x0000'0000'0000'0030ull}};
    EXPECT_DOUBLE_EQ(sum_intervals_ms(noisy, 36, 1.0f).at("pass"), 32 / 1e6);
}

}  // namespace
}  // namespace fg::vk
