#pragma once
// The CPU twin of a fractal.formula node: the program its GLSL runs (codegen/formula_glsl.h),
// interpreted in double over the stage bodies compiled into the twin.
#include <memory>
#include <vector>

#include "common/diagnostics.h"
#include "cpu/cpu_node_registry.h"
#include "cpu/cpu_value.h"
#include "ir/formula_program.h"

namespace fg {

class CpuFormula {
public:
    // Stages per group the twin runs (a longer group is refused with a message).
    static constexpr std::size_t kMaxStages = 32;
    static constexpr std::size_t kMaxStageInputs = 8, kMaxStageOutputs = 4;

    static std::shared_ptr<const CpuFormula> create(std::shared_ptr<const FormulaProgram> program, const std::string& node_id,
                                                    const std::string& pointer, Diagnostics& diag);
    // `in`: the formula node's inputs; `out`: distance, trap.
    void run(const CpuValue* in, CpuValue* out) const;

private:
    std::shared_ptr<const FormulaProgram> program_;
    std::vector<std::vector<CpuNodeFunction>> functions_;   // per group, per stage
    std::vector<std::vector<CpuTangentFunction>> tangents_; // per group, per stage (Jacobian formulas)

    // What one pass through a group writes: each stage's outputs and derivative. Made once per
    // evaluation, not per iteration (4 KB to clear).
    struct Scratch {
        CpuValue outs[kMaxStages][kMaxStageOutputs];
        double d[kMaxStages];
        CpuValue args[kMaxStageInputs];
    };
    // The orbit between iterations: `columns` (Jacobian formulas) are dz/dp over dr.
    struct Orbit {
        glm::dvec4 z, c;
        glm::dvec4 columns[3];
        double dr;
        int iteration;
    };
    CpuValue argument(const FormulaArg& a, const CpuValue* in, const Orbit& orbit, const Scratch& s) const;
    void iterate(int group, const CpuValue* in, Orbit& orbit, double bias, Scratch& s) const;
    // A Jacobian formula's pass: each node's tangent rule moves the columns.
    struct TangentScratch {
        CpuValue tangents[kMaxStages][kMaxStageOutputs][3];
        CpuValue args[kMaxStageInputs];
        CpuValue out[kMaxStageOutputs];
    };
    void iterate_jacobian(int group, const CpuValue* in, Orbit& orbit, double bias, Scratch& s, TangentScratch& t) const;
};

}  // namespace fg
