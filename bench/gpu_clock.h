#pragma once
// The shader clock of an NVIDIA GPU, read through NVML (the driver's libnvidia-ml, opened at run
// time), so a benchmark can say at what clock its GPU times were taken: an idle-looking load lets
// the driver drop an H100 from 1980 to 345 MHz within seconds, and every time with it.
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace fg::vk {
class Context;
}

namespace fg::bench {

class GpuClock {
public:
    // The GPU named `device_name` (the Vulkan device's name); nullptr without NVML or such a GPU.
    static std::unique_ptr<GpuClock> find(const std::string& device_name);
    ~GpuClock();
    GpuClock(const GpuClock&) = delete;
    GpuClock& operator=(const GpuClock&) = delete;

    std::optional<unsigned> sm_mhz() const;   // now
    unsigned max_sm_mhz() const { return max_mhz_; }

private:
    struct Nvml;
    GpuClock(std::unique_ptr<Nvml> nvml, void* device, unsigned max_mhz);
    std::unique_ptr<Nvml> nvml_;
    void* device_;
    unsigned max_mhz_;
};

// On a GPU, untimed frames before frames are timed: whatever ran before (pipeline builds, readbacks,
// comparisons) left it idle and its clock low, and it takes a busy spell to rise. Half a second at
// least; where NVML reads the clock, on until it is within 5 % of its maximum, 3 s at most (on an
// H100, after half a second, a head trace's first frame once ran at 690 of 1980 MHz). Nothing on a CPU device,
// which has no such clock.
void raise_gpu_clock(const vk::Context& ctx, const GpuClock* clock, const std::function<void()>& untimed_frame);

}  // namespace fg::bench
