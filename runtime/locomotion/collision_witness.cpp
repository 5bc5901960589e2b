#include "locomotion/collision_witness.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "compiler.h"
#include "cpu/cpu_evaluator.h"

namespace fg {

struct CollisionWitness::Twin {
    IrGraph ir;
    std::optional<CpuEvaluator> evaluator;
};

CollisionWitness::CollisionWitness(const Pack& pack) : twin_(std::make_unique<Twin>()) {
    Diagnostics diag;
    auto ir = load_and_lower(pack.graph, NodeLibrary::builtin(), diag);
    if (!ir) throw std::runtime_error("the pack's graph does not load for the CPU twin:\n" + diag.format());
    twin_->ir = std::move(*ir);
    twin_->evaluator = CpuEvaluator::create(twin_->ir, diag);
    if (!twin_->evaluator) throw std::runtime_error("the scene has no CPU twin:\n" + diag.format());
}

CollisionWitness::~CollisionWitness() = default;

void CollisionWitness::observe(const glm::dvec3& head) {
    double d = twin_->evaluator->distance(head);
    closest_ = std::min(closest_, d);
    ++frames_;
    if (d <= 0.0) ++inside_;
}

std::string CollisionWitness::summary() const {
    return fmt::format("collisions (CPU twin): closest head distance {:.5f} over {} frames, {} frames inside a surface",
                       frames_ ? closest_ : 0.0, frames_, inside_);
}

}  // namespace fg
