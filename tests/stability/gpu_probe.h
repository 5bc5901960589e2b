#pragma once
// The pack's probe pass run on its own: distance and normal at a list of points on the GPU
// (what collisions read back), so tests can look for NaN and Inf where float breaks first.
#include <vector>

#include <glm/glm.hpp>

#include "pack/pack_reader.h"
#include "vk/context.h"

namespace fg::test {

// x = distance, yzw = unit normal, one per point.
std::vector<glm::vec4> gpu_probe(const vk::Context& ctx, const Pack& pack, const std::vector<glm::dvec3>& points,
                                 float normal_step);

}  // namespace fg::test
