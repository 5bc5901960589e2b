#include "export_field.h"

#include <algorithm>

namespace fg {

double ExportBox::distance(const glm::dvec3& p) const {
    glm::dvec3 centre = 0.5 * (min + max), half = 0.5 * (max - min);
    glm::dvec3 q = glm::abs(p - centre) - half;
    return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

ExportField::ExportField(CpuEvaluator evaluator, double scale, double offset, ExportBox box)
    : evaluator_(std::move(evaluator)), scale_(scale), offset_(offset), box_(box) {}

double ExportField::operator()(const glm::dvec3& p) const {
    return std::max(evaluator_.distance(p) * scale_ - offset_, box_.distance(p));
}

}  // namespace fg
