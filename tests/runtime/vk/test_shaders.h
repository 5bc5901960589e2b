#pragma once
// The test shaders' SPIR-V, compiled by glslangValidator at build time (see CMakeLists.txt).
#include <cstdint>

namespace fg::vk::test::shaders {
#include "shaders/busy.spv.h"
#include "shaders/double_values.spv.h"
#include "shaders/fill.spv.h"
#include "shaders/float64.spv.h"
#include "shaders/sample_image.spv.h"
#include "shaders/scale_by_uniform.spv.h"
#include "shaders/specialized.spv.h"
#include "shaders/write_image.spv.h"
}  // namespace fg::vk::test::shaders
