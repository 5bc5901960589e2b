#pragma once
// Where the samples of a pixel fall: sub-pixel offsets of the whole pixel grid, one per frame of an
// accumulated or temporally filtered picture (StereoSettings::jitter), in pixels, each coordinate
// in [-0.5, 0.5).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace fg {

// The offsets of n samples: none for one (the pixel's centre, as an unjittered frame); for a square
// number s^2 the centres of an s x s grid of cells, the same points as --supersample s; otherwise
// the Halton (2, 3) sequence. Grid cells come in the order the Halton sequence first visits them,
// so every prefix covers the pixel evenly (a picture stopped early is not lopsided).
std::vector<glm::dvec2> sample_pattern(std::uint32_t n);

// Frames a still view takes to average each of taa_jitter's 16 offsets once.
inline constexpr std::uint32_t kRefinedFrames = 16;

// Where n samples fall on a lens of unit radius: the Halton (5, 7) points (not the bases of
// sample_pattern, so a sample's lens position and its place in the pixel do not follow each other),
// mapped to the disc by Shirley and Chiu's concentric map, which keeps them evenly spread.
std::vector<glm::dvec2> lens_pattern(std::uint32_t n);

// When n samples look within an open shutter, in [0, 1): the radical inverse in base 11, another
// base again, so a sample's moment follows neither its place in the pixel nor on the lens.
std::vector<double> shutter_pattern(std::uint32_t n);

// The offsets temporal anti-aliasing cycles through, upsampling by `upscale` (1: none): a (4u)^2
// grid over a marched pixel, so that each output pixel gets a 4x4 grid of samples, 16 as without
// upsampling (36 offsets at 1.5, 64 at 2).
std::uint32_t taa_phases(double upscale);

// Temporal anti-aliasing's offset for the frame after `history_frames` frames of history
// (FrameExecutor::history_frames): the samples of sample_pattern(taa_phases(upscale)), one per
// frame, repeating.
glm::dvec2 taa_jitter(std::uint64_t history_frames, double upscale = 1.0);

}  // namespace fg
