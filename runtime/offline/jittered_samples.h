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

// The same with motion blur: sample k looks from `moment(u)`, u its place in the open shutter in
// [0, 1) (shutter_pattern); `moment` also sets whatever else moves with it (world scale, keyed
// parameters) on the renderer.
RenderedFrame render_samples(HeadlessRenderer& renderer, const std::function<SampleMoment(double)>& moment,
                             std::uint32_t frame_index, std::uint32_t samples);

}  // namespace fg
