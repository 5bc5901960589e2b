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

// Temporal anti-aliasing's offset for the frame after `history_frames` frames of history
// (FrameExecutor::history_frames): the 16 samples of sample_pattern(16) (a 4x4 grid), one per
// frame, repeating.
glm::dvec2 taa_jitter(std::uint64_t history_frames);

}  // namespace fg
