#pragma once
// The accuracy knobs the benchmark sweeps: one at a time around the default, then jointly on a
// small grid. Each setting is a frame configuration: stereo mode, conemarch levels, resolution and
// specialization-constant overrides.
#include <map>
#include <string>
#include <vector>

#include "frame/frame_settings.h"
#include "pack/manifest.h"

namespace fg::bench {

// The group of the settings that drop or thin a light term: a cheaper look, not a more or less
// accurate march.
inline constexpr const char* kLightTermGroup = "light terms";

struct BenchSetting {
    std::string name;        // "epsilon=1", "grid: reproject-trust eps=1 ..."
    std::string group;       // the knob swept ("epsilon", "grid", "baseline", ...)
    FrameSettings frame;
    bool baseline = false;
};

struct SweepOptions {
    bool quick = false;
    std::uint32_t size = 512;
};

// `m` supplies the node knobs (iterations.<node>, bias.<node>) to sweep.
std::vector<BenchSetting> make_sweep(const PackManifest& m, const SweepOptions& o);

}  // namespace fg::bench
