#pragma once
// The settings `fgplay bench --sequence` flies every head trace with, in one list: a setting added
// here (cross-frame reuse, say) is measured, reported and plotted like the others. Each method
// runs on all pixels and again with the lens mask and foveation 0.5; speed-ups compare a setting
// with the two baselines of its own pixel set.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "frame/frame_settings.h"

namespace fg::bench {

enum class SequenceBaseline {
    None,
    Naive,             // naive per-eye sphere tracing: what every speed-up is first measured against
    NaivePersistent,   // the same with persistent lanes: whether a method beats the better-scheduled naive tracer
};

struct SequenceSetting {
    std::string method;   // "naive", "naive + persistent lanes", "per-eye", ...
    std::string pixels;   // kAllPixels or kMaskedPixels
    FrameSettings frame;
    SequenceBaseline baseline = SequenceBaseline::None;

    std::string name() const;   // unique: the method, and the pixel set when it is not all of them
};

inline constexpr const char* kAllPixels = "all pixels";
inline constexpr const char* kMaskedPixels = "lens mask + foveation 0.5";

// Per-eye conemarch with some knobs changed, flown beside the fixed settings (`--variant
// cone_steps=16`): a lever measured in the same run as its baselines, on both pixel sets.
struct SequenceVariant {
    std::map<std::string, double> knobs;
    std::string method() const;   // "per-eye + cone_steps=16"
};

// "knob=value[,knob=value]". False, with `error` naming the text, where it is not that.
bool parse_sequence_variant(const std::string& text, SequenceVariant& out, std::string& error);

// `quick`: the methods on all pixels only.
std::vector<SequenceSetting> make_sequence_settings(std::uint32_t size, bool quick,
                                                    const std::vector<SequenceVariant>& variants = {});

}  // namespace fg::bench
