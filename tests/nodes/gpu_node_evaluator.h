#pragma once
// Runs one node body on the GPU (lavapipe in CI) at many points in one dispatch: the evaluation
// shader from node_harness goes through the real glslang pipeline and fg_vk.
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.h"
#include "cpu/cpu_value.h"
#include "graph/node_definition.h"
#include "vk/context.h"

namespace fg::test {

class GpuNodeEvaluator {
public:
    // One Vulkan context for the whole test program, with validation on.
    static GpuNodeEvaluator& shared();

    // `inputs` holds count * def.inputs.size() values, point by point; the answer holds
    // count * def.outputs.size(). nullopt (with diagnostics) when the shader does not compile.
    std::optional<std::vector<CpuValue>> evaluate(const NodeDefinition& def, std::optional<ValueType> generic,
                                                  const std::vector<CpuValue>& inputs, std::size_t count,
                                                  Diagnostics& diag, bool in_double = false);
    // Runs a compute shader written like evaluation_shader(): `inputs` vec4s (dvec4 with
    // in_double) at binding 0, `count * outputs_per_point` results at binding 1.
    std::optional<std::vector<CpuValue>> run(const std::string& name, const std::string& glsl,
                                             const std::vector<CpuValue>& inputs, std::size_t count,
                                             std::size_t outputs_per_point, bool in_double, Diagnostics& diag);
    const vk::Context& context() const { return ctx_; }

private:
    GpuNodeEvaluator();
    vk::Context ctx_;
};

}  // namespace fg::test
