#pragma once
// How many workgroups a persistent-lanes dispatch launches (lane_queue.glsl). Enough that its lanes
// can take every index of the queue within their loop bound (FG_LANE_PIXELS), and on a GPU enough
// to fill the device: sized by the loop bound alone, a 512² eye launched 16,384 lanes, a sixteenth
// of what an H100 runs at once. Extra groups cost little: they start when the queue runs dry.
#include <cstdint>

namespace fg {

// Invocations to launch at least. `requested` > 0 wins (FrameSettings::persistent_invocations). A CPU
// device gets none beyond the loop bound (llvmpipe runs a workgroup to its end before the next, so
// the first groups drain the queue whatever the count). A GPU gets what it runs at once
// (`resident`), or a quarter of the queue's length (four pixels a lane) when it does not say.
std::uint64_t persistent_fill(std::uint64_t queue_length, bool cpu_device, std::uint64_t resident,
                              std::uint64_t requested);

// Workgroups of `group_invocations` for a queue of `queue_length` indices: the loop bound's count,
// raised to launch `fill` invocations, but never more groups than give every lane one index.
std::uint32_t persistent_group_count(std::uint64_t queue_length, std::uint32_t group_invocations, std::uint64_t fill);

}  // namespace fg
