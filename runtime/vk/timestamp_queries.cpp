#include "vk/timestamp_queries.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "vk/context.h"
#include "vk/vulkan_error.h"

namespace fg::vk {

std::map<std::string, double> sum_intervals_ms(std::span<const TimedInterval> intervals, std::uint32_t valid_bits,
                                               float period_ns) {
    const std::uint64_t mask = valid_bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << valid_bits) - 1;
    std::map<std::string, double> totals;
    for (const TimedInterval& interval : intervals) {
        const std::uint64_t ticks = ((interval.end & mask) - (interval.begin & mask)) & mask;
        totals[interval.label] += static_cast<double>(ticks) * static_cast<double>(period_ns) / 1.0e6;
    }
    return totals;
}

GpuTimer::GpuTimer(const Context& ctx, std::uint32_t max_passes) : ctx_(&ctx), query_count_(max_passes * 2) {
    if (!ctx.timestamps_supported())
        throw VulkanError(VK_ERROR_FEATURE_NOT_PRESENT,
                          fmt::format("{} cannot write timestamps on its compute queue", ctx.device_name()));
    if (max_passes == 0) throw std::invalid_argument("a GpuTimer needs room for at least one pass");

    VkQueryPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = query_count_;
    check(vkCreateQueryPool(ctx.device(), &info, nullptr, &pool_), "vkCreateQueryPool");

    // New queries are in an undefined state; with host reset the timer is usable at once.
    if (ctx.host_query_reset_enabled()) reset();
}

GpuTimer::~GpuTimer() { destroy(); }

GpuTimer::GpuTimer(GpuTimer&& other) noexcept
    : ctx_(other.ctx_),
      pool_(std::exchange(other.pool_, VK_NULL_HANDLE)),
      query_count_(std::exchange(other.query_count_, 0)),
      used_queries_(std::exchange(other.used_queries_, 0)),
      was_reset_(std::exchange(other.was_reset_, false)),
      passes_(std::move(other.passes_)) {}

GpuTimer& GpuTimer::operator=(GpuTimer&& other) noexcept {
    if (this != &other) {
        destroy();
        ctx_ = other.ctx_;
        pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
        query_count_ = std::exchange(other.query_count_, 0);
        used_queries_ = std::exchange(other.used_queries_, 0);
        was_reset_ = std::exchange(other.was_reset_, false);
        passes_ = std::move(other.passes_);
    }
    return *this;
}

void GpuTimer::destroy() noexcept {
    if (pool_) vkDestroyQueryPool(ctx_->device(), pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
}

void GpuTimer::reset(VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, pool_, 0, query_count_);
    passes_.clear();
    used_queries_ = 0;
    was_reset_ = true;
}

void GpuTimer::reset() {
    if (!ctx_->host_query_reset_enabled())
        throw std::logic_error(fmt::format("{} has no hostQueryReset; record GpuTimer::reset(cmd) instead",
                                           ctx_->device_name()));
    vkResetQueryPool(ctx_->device(), pool_, 0, query_count_);
    passes_.clear();
    used_queries_ = 0;
    was_reset_ = true;
}

std::uint32_t GpuTimer::next_query() {
    if (!was_reset_) throw std::logic_error("GpuTimer used before reset");
    return used_queries_++;
}

void GpuTimer::begin(VkCommandBuffer cmd, std::string_view label) {
    std::uint32_t open_passes = 0;
    for (const Pass& p : passes_) {
        if (p.end_query) continue;
        if (p.label == label) throw std::logic_error(fmt::format("GPU pass '{}' is begun twice", label));
        ++open_passes;
    }
    // Room for this begin and the end of every open pass, this one included: a pair with no
    // end could never be read.
    if (was_reset_ && used_queries_ + open_passes + 2 > query_count_)
        throw std::logic_error(fmt::format("GpuTimer is full: {} passes since the last reset", max_passes()));
    const std::uint32_t query = next_query();
    // Written once earlier compute work is done, so the pass's own work starts the clock.
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, pool_, query);
    passes_.push_back({std::string(label), query, std::nullopt});
}

void GpuTimer::end(VkCommandBuffer cmd, std::string_view label) {
    auto pass = std::find_if(passes_.begin(), passes_.end(),
                             [&](const Pass& p) { return p.label == label && !p.end_query; });
    if (pass == passes_.end()) throw std::logic_error(fmt::format("GPU pass '{}' is ended but was not begun", label));
    const std::uint32_t query = next_query();
    // ALL_COMMANDS: the clock stops only when everything recorded before, of any kind, is done.
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, query);
    pass->end_query = query;
}

std::map<std::string, double> GpuTimer::results() const {
    for (const Pass& p : passes_)
        if (!p.end_query) throw std::logic_error(fmt::format("GPU pass '{}' was begun but not ended", p.label));
    if (used_queries_ == 0) return {};

    std::vector<std::uint64_t> ticks(used_queries_);
    // No WAIT flag: waiting on queries that were never submitted would block forever.
    const VkResult result = vkGetQueryPoolResults(ctx_->device(), pool_, 0, used_queries_,
                                                  ticks.size() * sizeof(std::uint64_t), ticks.data(),
                                                  sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT);
    if (result == VK_NOT_READY)
        throw std::logic_error("GPU timestamps are not available yet: submit the work and wait for it first");
    check(result, "vkGetQueryPoolResults");

    std::vector<TimedInterval> intervals;
    for (const Pass& p : passes_) intervals.push_back({p.label, ticks[p.begin_query], ticks[*p.end_query]});
    return sum_intervals_ms(intervals, ctx_->timestamp_valid_bits(), ctx_->timestamp_period_ns());
}

}  // namespace fg::vk
