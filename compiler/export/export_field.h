#pragma once
// The distance an export samples: the graph's estimate made a conservative distance (times
// step_factor / Lipschitz bound, as the march steps), moved out by an offset and cut by the box.
// The cut is max(distance, box distance), so where the box crops the shape the surface is closed
// by the box's faces and every mesh of it is watertight.
#include <glm/glm.hpp>

#include "cpu/cpu_evaluator.h"

namespace fg {

struct ExportBox {
    glm::dvec3 min{-1.0}, max{1.0};

    glm::dvec3 size() const { return max - min; }
    // Exact signed distance to the box (negative inside).
    double distance(const glm::dvec3& p) const;
};

class ExportField {
public:
    // scale: the factor that makes the estimate a distance that never overestimates;
    // offset: how far out the surface moves (0: the estimate's zero set; > 0 grows the shape).
    ExportField(CpuEvaluator evaluator, double scale, double offset, ExportBox box);

    double operator()(const glm::dvec3& p) const;
    const ExportBox& box() const { return box_; }
    const CpuEvaluator& evaluator() const { return evaluator_; }
    double scale() const { return scale_; }
    double offset() const { return offset_; }

private:
    CpuEvaluator evaluator_;
    double scale_, offset_;
    ExportBox box_;
};

}  // namespace fg
