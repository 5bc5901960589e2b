#pragma once
// GPU time per labelled pass, from pairs of timestamp queries around the recorded work.
//
//     GpuTimer timer(ctx);
//     timer.reset(cmd);                 // or timer.reset() on the host between frames
//     timer.begin(cmd, "march");
//     pipeline.dispatch(cmd, ...);
//     timer.end(cmd, "march");
//     ... submit, wait for the fence ...
//     double ms = timer.results().at("march");
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

namespace fg::vk {

class Context;

// Raw ticks of one begin/end pair.
struct TimedInterval {
    std::string label;
    std::uint64_t begin = 0;
    std::uint64_t end = 0;
};

// Milliseconds per label, summed over every interval with that label. Only the low `valid_bits`
// of each tick count are meaningful, so differences are taken modulo 2^valid_bits: a counter
// that wrapped between begin and end still gives the right (small) duration.
std::map<std::string, double> sum_intervals_ms(std::span<const TimedInterval> intervals, std::uint32_t valid_bits,
                                               float period_ns);

class GpuTimer {
public:
    // Room for `max_passes` begin/end pairs. Throws VulkanError(VK_ERROR_FEATURE_NOT_PRESENT)
    // when the context's queue cannot write timestamps.
    explicit GpuTimer(const Context& ctx, std::uint32_t max_passes = 32);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;
    GpuTimer(GpuTimer&& other) noexcept;
    GpuTimer& operator=(GpuTimer&& other) noexcept;

    VkQueryPool pool() const { return pool_; }
    std::uint32_t max_passes() const { return query_count_ / 2; }

    // Forgets recorded passes and resets the queries, either in `cmd` (before any begin() in it)
    // or right now on the host (needs hostQueryReset; the pool must not be in use).
    void reset(VkCommandBuffer cmd);
    void reset();

    // A label may be timed several times between resets; its durations are summed. Different
    // labels may nest or overlap. Throws std::logic_error when a label is begun twice, ended
    // without begin, begun before any reset, or the pool is full.
    void begin(VkCommandBuffer cmd, std::string_view label);
    void end(VkCommandBuffer cmd, std::string_view label);

    // Label -> milliseconds. Call after the work has finished (fence waited); throws
    // std::logic_error when a pass is still open or its timestamps are not available yet.
    std::map<std::string, double> results() const;

private:
    struct Pass {
        std::string label;
        std::uint32_t begin_query = 0;
        std::optional<std::uint32_t> end_query;
    };

    std::uint32_t next_query();
    void destroy() noexcept;

    const Context* ctx_ = nullptr;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    std::uint32_t query_count_ = 0;
    std::uint32_t used_queries_ = 0;
    bool was_reset_ = false;
    std::vector<Pass> passes_;
};

}  // namespace fg::vk
