#pragma once
// Reading a rendered frame's AOV images pixel by pixel, for tests that check them against closed forms.
#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "frame/headless_renderer.h"

namespace fg::test {

// Channel c of pixel i of the left eye's AOV image `name`, one of the half-float images (all but
// the position).
double aov_half(const RenderedFrame& f, const std::string& name, std::size_t i, int c);
// The left eye's position AOV at pixel i: xyz the world position, w the camera depth (not finite:
// a miss).
glm::dvec4 aov_position(const RenderedFrame& f, std::size_t i);
// Channel c of pixel i of the left eye's linear HDR beauty.
inline double aov_beauty(const RenderedFrame& f, std::size_t i, int c) { return aov_half(f, "beauty", i, c); }
// Whether pixel i's ray met the surface.
inline bool aov_hit(const RenderedFrame& f, std::size_t i) { return std::isfinite(aov_position(f, i).w); }

}  // namespace fg::test
