#pragma once
// One frame as N jittered samples per pixel (`fgplay render --samples N`, stills and paths): N
// frames of the same pose and time, each with its pixel grid moved by sample_pattern(N)[k], averaged
// in linear light by a SampleAccumulator. Every sample hits by the same output pixel, so the mean
// is the same picture as --supersample of as many samples, in the memory of one frame.
#include <cstdint>
#include <functional>

#include "frame/headless_renderer.h"

namespace fg {

inline constexpr std::uint32_t kMaxSamples = 4096;

// With the renderer's depth of field (HeadlessRenderer::set_depth_of_field), each sample also
// looks through its own point of the lens (lens_pattern), so the mean is the thin lens's picture.
// The first sample's frame with its pictures (and beauty AOVs) replaced by the mean of all
// `samples`; depth and the other AOVs stay the first sample's. Stats are summed over the samples.
// The renderer's jitter is none again afterwards.
RenderedFrame render_samples(HeadlessRenderer& renderer, const HeadPose& head, double time, std::uint32_t frame_index,
                             std::uint32_t samples);

// Where and when a sample looks from.
struct SampleMoment {
    HeadPose head;
    double time = 0.0;
};

// Where a frame's sampling stands, after each sample.
struct SampleProgress {
    std::uint32_t sample = 0, samples = 0;   // samples taken, and at most
    double tiles_sampling = 1.0;             // the share of both eyes' tiles that take the next sample
    double mean_samples = 0.0;               // per pixel so far
    std::size_t noisy_pixels = 0;            // pixels whose noise is still above the target
};

// How many samples a frame takes. With a noise target (adaptive sampling) a pixel stops once the
// standard error of its mean is below `noise` (display units: 1/255 is one step of an 8-bit
// value), after at least `min_samples`; its 8x8 tile, and the tiles around, stop when all of its
// pixels have (the passes march and shade by tiles). Needs tile dispatch (FrameSettings).
struct SampleBudget {
    std::uint32_t samples = 1;
    double noise = 0.0;                     // 0: every pixel takes every sample
    std::uint32_t min_samples = 16;
    std::function<void(const SampleProgress&)> progress;   // called after each sample
};

// The same with motion blur: sample k looks from `moment(u)`, u its place in the open shutter in
// [0, 1) (shutter_pattern); `moment` also sets whatever else moves with it (world scale, keyed
// parameters) on the renderer.
RenderedFrame render_samples(HeadlessRenderer& renderer, const std::function<SampleMoment(double)>& moment,
                             std::uint32_t frame_index, std::uint32_t samples);
RenderedFrame render_samples(HeadlessRenderer& renderer, const std::function<SampleMoment(double)>& moment,
                             std::uint32_t frame_index, const SampleBudget& budget);

}  // namespace fg
