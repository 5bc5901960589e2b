#pragma once
// A value in the CPU twin: every type fits in a dvec4 (ints and bools as exact doubles).
#include <glm/glm.hpp>

#include "common/value_type.h"

namespace fg {

struct CpuValue {
    glm::dvec4 v{0.0};

    double f() const { return v.x; }
    int i() const { return static_cast<int>(v.x); }
    bool b() const { return v.x != 0.0; }
    glm::dvec2 v2() const { return {v.x, v.y}; }
    glm::dvec3 v3() const { return {v.x, v.y, v.z}; }
    glm::dvec4 v4() const { return v; }

    static CpuValue of(double x) { return {glm::dvec4(x, 0.0, 0.0, 0.0)}; }
    static CpuValue of(int x) { return of(static_cast<double>(x)); }
    static CpuValue of(bool x) { return of(x ? 1.0 : 0.0); }
    static CpuValue of(glm::dvec2 x) { return {glm::dvec4(x, 0.0, 0.0)}; }
    static CpuValue of(glm::dvec3 x) { return {glm::dvec4(x, 0.0)}; }
    static CpuValue of(glm::dvec4 x) { return {x}; }
    static CpuValue of(const Constant& c) { return {glm::dvec4(c.v[0], c.v[1], c.v[2], c.v[3])}; }
    Constant to_constant(ValueType t) const { return Constant::vector(t, {v.x, v.y, v.z, v.w}); }
};

}  // namespace fg
