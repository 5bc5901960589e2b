#pragma once
// Reading a rendered frame's AOV images pixel by pixel, for tests that check them against closed forms.
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

}  // namespace fg::test
