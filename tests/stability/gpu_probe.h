#pragma once
// The pack's probe pass run on its own: distance and normal at a list of points on the GPU
// (what collisions read back), so tests can look for NaN and Inf where float breaks first.
#include <vector>

#include <glm/glm.hpp>

#include "pack/pack_reader.h"
#include "vk/context.h"

namespace fg::test {

// x = distance, yzw = unit normal, one per point. A pack of precision "double" gets the points
// relative to `anchor` (in double, as the runtime's probes do); a float pack ignores it.
std::vector<glm::vec4> gpu_probe(const vk::Context& ctx, const Pack& pack, const std::vector<glm::dvec3>& points,
                                 float normal_step, glm::dvec3 anchor = glm::dvec3(0.0));

}  // namespace fg::test
