#pragma once
// The CPU twin of a compiled scene: evaluates the IR in double precision by calling each node's
// body compiled as C++. Ground truth for tests, the calibration's bubble search, collision probes
// and `fgc probe`. Not fast, but exact where the GPU is float.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/diagnostics.h"
#include "cpu/cpu_formula.h"
#include "cpu_node_registry.h"
#include "ir/ir_graph.h"

namespace fg {

// What the shading context supplies at a hit.
struct CpuShadeInputs {
    glm::dvec3 to_camera{0.0, 0.0, 1.0};
    glm::dvec3 normal{0.0, 1.0, 0.0};
};

struct CpuSurface {
    glm::dvec3 albedo{0.8};
    std::optional<double> diffuse, ao, sss, rim, shadow;
    glm::dvec3 emission{0.0};
    glm::dvec3 specular{0.0};
    glm::dvec3 specular_color{0.0};
    double roughness = 0.35;
    glm::dvec3 reflection{0.0};
    glm::dvec3 transmission{0.0};
    double ior = 1.5;
    glm::dvec3 absorption{0.0};
};

class CpuEvaluator {
public:
    static constexpr std::size_t kMaxNodeInputs = 32;
    // nullopt (with a diagnostic naming the node) when a node has no CPU twin, e.g. custom GLSL.
    static std::optional<CpuEvaluator> create(const IrGraph& ir, Diagnostics& diag);

    // Parameter values (uniforms); defaults come from the graph.
    bool set_param(const std::string& name, const Constant& value);
    // Knob values (specialization constants) by their manifest name, e.g. "bias.bulb".
    bool set_knob(const std::string& spec_name, double value);
    void set_time(double seconds) { time_ = seconds; }
    // Moves one node's distance output out by `offset` before anything reads it (the export's
    // surface rule for a part whose estimate has no inside); false when it has no distance output.
    bool move_surface(int node, double offset);
    // A copy whose distance() is this node's own distance output: one part of the scene alone.
    CpuEvaluator part(int node) const;

    double distance(const glm::dvec3& p) const;
    // Normal by central differences of the double-precision distance.
    glm::dvec3 normal(const glm::dvec3& p, double h = 1e-6) const;
    CpuSurface surface(const glm::dvec3& p, const CpuShadeInputs& shade) const;
    // Any graph output, for tests ("distance", "albedo", ...).
    std::optional<CpuValue> output(const std::string& name, const glm::dvec3& p, const CpuShadeInputs& shade) const;
    // Every output of every node that does not need the shading context, at point p: for the
    // analyses that sample values (see slot()).
    std::vector<CpuValue> evaluate_nodes(const glm::dvec3& p) const;
    std::size_t slot(int node, int port) const { return slot_offset_[static_cast<std::size_t>(node)] + static_cast<std::size_t>(port); }
    // Evaluate one node whose inputs are all constants (constant folding).
    static std::optional<std::vector<CpuValue>> evaluate_constant_node(const IrNode& node);

    const IrGraph& ir() const { return *ir_; }
    std::uint64_t evaluations() const { return evaluations_; }

private:
    explicit CpuEvaluator(const IrGraph& ir);
    struct Plan {
        std::vector<int> nodes;   // IR node indices to run, in order
    };
    Plan plan_for(const std::vector<const IrInput*>& roots) const;
    CpuValue read(const IrInput& in, const std::vector<CpuValue>& slots, const glm::dvec3& p,
                  const CpuShadeInputs* shade) const;
    void run(const Plan& plan, std::vector<CpuValue>& slots, const glm::dvec3& p, const CpuShadeInputs* shade) const;

    const IrGraph* ir_;
    std::vector<CpuNodeFunction> functions_;
    std::vector<std::shared_ptr<const CpuFormula>> formulas_;   // fractal.formula nodes (else null)
    std::vector<std::size_t> slot_offset_;   // first output slot of each node
    std::size_t slot_count_ = 0;
    std::vector<CpuValue> params_;
    std::map<std::pair<int, int>, double> knobs_;  // (node, input) -> value override
    std::vector<std::pair<int, double>> surface_moves_;   // per node: its distance port (-1: none) and offset
    IrInput distance_root_;
    double time_ = 0.0;
    Plan distance_plan_, all_plan_, unshaded_plan_;
    mutable std::uint64_t evaluations_ = 0;
};

// Makes `scene` the distance that shade-context node bodies call (fg_scene_distance) for one scope,
// so a test can call such a body directly, as the GPU does inside the shade pass.
class CpuShadingScope {
public:
    explicit CpuShadingScope(const CpuEvaluator& scene);
    ~CpuShadingScope();
    CpuShadingScope(const CpuShadingScope&) = delete;
    CpuShadingScope& operator=(const CpuShadingScope&) = delete;

private:
    const CpuEvaluator* previous_;
};

}  // namespace fg
