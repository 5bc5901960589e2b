#pragma once
// The shader clock of an NVIDIA GPU, read through NVML (the driver's libnvidia-ml, opened at run
// time), so a benchmark can say at what clock its GPU times were taken: an idle-looking load lets
// the driver drop an H100 from 1980 to 345 MHz within seconds, and every time with it.
#include <memory>
#include <optional>
#include <string>

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

}  // namespace fg::bench
