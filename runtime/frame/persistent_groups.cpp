#include "persistent_groups.h"

#include <algorithm>

#include "frame/shaders/gpu_interface.h"

namespace fg {

std::uint64_t persistent_fill(std::uint64_t queue_length, bool cpu_device, std::uint64_t resident,
                              std::uint64_t requested) {
    if (requested > 0) return requested;
    if (cpu_device) return 0;
    return resident > 0 ? resident : queue_length / 4;
}

std::uint32_t persistent_group_count(std::uint64_t queue_length, std::uint32_t group_invocations, std::uint64_t fill) {
    const std::uint64_t group = std::max<std::uint32_t>(1, group_invocations);
    auto groups_for = [&](std::uint64_t invocations) { return (invocations + group - 1) / group; };
    // Half a lane's bound on average, so the lanes can take every index even when the first groups
    // to run take all they may.
    const std::uint64_t bounded = groups_for((queue_length + FG_LANE_PIXELS / 2 - 1) / (FG_LANE_PIXELS / 2));
    const std::uint64_t filling = std::min(groups_for(fill), groups_for(queue_length));
    return static_cast<std::uint32_t>(std::max<std::uint64_t>({1, bounded, filling}));
}

}  // namespace fg
