#include "gpu_clock.h"

#include <dlfcn.h>

#include <chrono>

#include "vk/context.h"

namespace fg::bench {

namespace {
// The few NVML entry points used, as its header (nvml.h, not in Debian main) declares them.
using NvmlReturn = int;   // NVML_SUCCESS is 0
constexpr int kClockSm = 1;   // NVML_CLOCK_SM
using Init = NvmlReturn (*)();
using GetCount = NvmlReturn (*)(unsigned*);
using GetHandle = NvmlReturn (*)(unsigned, void**);
using GetName = NvmlReturn (*)(void*, char*, unsigned);
using GetClock = NvmlReturn (*)(void*, int, unsigned*);
}  // namespace

struct GpuClock::Nvml {
    void* library = nullptr;
    GetClock clock = nullptr, max_clock = nullptr;
    NvmlReturn (*shutdown)() = nullptr;
    ~Nvml() {
        if (shutdown) shutdown();
        if (library) dlclose(library);
    }
};

std::unique_ptr<GpuClock> GpuClock::find(const std::string& device_name) {
    auto nvml = std::make_unique<Nvml>();
    nvml->library = dlopen("libnvidia-ml.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!nvml->library) return nullptr;
    auto sym = [&](const char* name) { return dlsym(nvml->library, name); };
    auto init = reinterpret_cast<Init>(sym("nvmlInit_v2"));
    auto count = reinterpret_cast<GetCount>(sym("nvmlDeviceGetCount_v2"));
    auto handle = reinterpret_cast<GetHandle>(sym("nvmlDeviceGetHandleByIndex_v2"));
    auto name = reinterpret_cast<GetName>(sym("nvmlDeviceGetName"));
    nvml->clock = reinterpret_cast<GetClock>(sym("nvmlDeviceGetClockInfo"));
    nvml->max_clock = reinterpret_cast<GetClock>(sym("nvmlDeviceGetMaxClockInfo"));
    auto shutdown = reinterpret_cast<NvmlReturn (*)()>(sym("nvmlShutdown"));
    if (!init || !count || !handle || !name || !nvml->clock || !nvml->max_clock || !shutdown || init() != 0)
        return nullptr;
    nvml->shutdown = shutdown;
    unsigned devices = 0;
    if (count(&devices) != 0) return nullptr;
    for (unsigned i = 0; i < devices; ++i) {
        void* device = nullptr;
        char text[96] = {};
        unsigned max_mhz = 0;
        if (handle(i, &device) != 0 || name(device, text, sizeof text) != 0 || device_name != text) continue;
        if (nvml->max_clock(device, kClockSm, &max_mhz) != 0) continue;
        return std::unique_ptr<GpuClock>(new GpuClock(std::move(nvml), device, max_mhz));
    }
    return nullptr;
}

GpuClock::GpuClock(std::unique_ptr<Nvml> nvml, void* device, unsigned max_mhz)
    : nvml_(std::move(nvml)), device_(device), max_mhz_(max_mhz) {}

GpuClock::~GpuClock() = default;

std::optional<unsigned> GpuClock::sm_mhz() const {
    unsigned mhz = 0;
    if (nvml_->clock(device_, kClockSm, &mhz) != 0) return std::nullopt;
    return mhz;
}

void raise_gpu_clock(const vk::Context& ctx, const GpuClock* clock, const std::function<void()>& untimed_frame) {
    if (ctx.is_cpu_device()) return;
    using namespace std::chrono;
    const auto started = steady_clock::now();
    auto clock_is_up = [&] {
        const auto mhz = clock ? clock->sm_mhz() : std::nullopt;
        return !mhz || *mhz * 20 >= clock->max_sm_mhz() * 19;
    };
    for (;;) {
        untimed_frame();
        const auto spent = steady_clock::now() - started;
        if (spent >= seconds(3) || (spent >= milliseconds(500) && clock_is_up())) return;
    }
}

}  // namespace fg::bench
