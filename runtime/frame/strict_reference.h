#pragma once
// The strict reference every speed setting is judged against: naive sphere tracing of both eyes
// with a tenth of the default hit threshold, a generous step cap, and half the pack's step.
//
// Half steps, because the distance estimate of an iterated fractal still overshoots near its
// surface after the derivative bias (docs/stability.md): a tracer with full steps passes through
// sub-pixel detail that smaller steps find. A full-step reference extends the naive tracer's own
// chain of samples, so the naive tracer could never overstep against it while any other tracer,
// sampling elsewhere, did (the conemarch's "oversteps" of issue 19: docs/accuracy.md).
#include <cstdint>

#include "frame_settings.h"
#include "pack/manifest.h"

namespace fg {

FrameSettings strict_reference_settings(const PackManifest& pack, std::uint32_t width, std::uint32_t height);

}  // namespace fg
