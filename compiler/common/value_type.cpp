#include "value_type.h"

#include <cmath>
#include <fmt/format.h>

namespace fg {

std::string_view type_name(ValueType t) {
    switch (t) {
        case ValueType::Float: return "float";
        case ValueType::Int: return "int";
        case ValueType::Bool: return "bool";
        case ValueType::Vec2: return "vec2";
        case ValueType::Vec3: return "vec3";
        case ValueType::Vec4: return "vec4";
    }
    return "?";
}

std::optional<ValueType> parse_type(std::string_view s) {
    for (auto t : {ValueType::Float, ValueType::Int, ValueType::Bool, ValueType::Vec2, ValueType::Vec3, ValueType::Vec4})
        if (type_name(t) == s) return t;
    return std::nullopt;
}

int component_count(ValueType t) {
    switch (t) {
        case ValueType::Vec2: return 2;
        case ValueType::Vec3: return 3;
        case ValueType::Vec4: return 4;
        default: return 1;
    }
}

bool is_vector(ValueType t) { return component_count(t) > 1; }

bool is_float_like(ValueType t) { return t != ValueType::Int && t != ValueType::Bool; }

ValueType float_vector(int components) {
    switch (components) {
        case 2: return ValueType::Vec2;
        case 3: return ValueType::Vec3;
        case 4: return ValueType::Vec4;
        default: return ValueType::Float;
    }
}

Constant Constant::scalar(ValueType t, double x) {
    Constant c;
    c.type = t;
    c.v = {x, x, x, x};
    if (is_vector(t)) return c;  // a scalar broadcast to every component
    c.v = {x, 0, 0, 0};
    return c;
}

Constant Constant::vector(ValueType t, std::array<double, 4> xs) {
    Constant c;
    c.type = t;
    c.v = xs;
    for (int i = component_count(t); i < 4; ++i) c.v[static_cast<std::size_t>(i)] = 0;
    return c;
}

double Constant::max_abs() const {
    double m = 0;
    for (int i = 0; i < component_count(type); ++i) m = std::max(m, std::abs(v[static_cast<std::size_t>(i)]));
    return m;
}

namespace {
// Shortest text that reads back as the same float, always with a decimal point so GLSL types it float.
std::string float_literal(double x) {
    float f = static_cast<float>(x);
    std::string s = fmt::format("{}", f);
    if (s.find_first_of(".eE") == std::string::npos && s.find("inf") == std::string::npos) s += ".0";
    return s;
}
}  // namespace

std::string Constant::glsl() const {
    switch (type) {
        case ValueType::Float: return float_literal(v[0]);
        case ValueType::Int: return fmt::format("{}", static_cast<long long>(v[0]));
        case ValueType::Bool: return v[0] != 0 ? "true" : "false";
        default: break;
    }
    std::string s = std::string(type_name(type)) + "(";
    for (int i = 0; i < component_count(type); ++i) {
        if (i) s += ", ";
        s += float_literal(v[static_cast<std::size_t>(i)]);
    }
    return s + ")";
}

std::string Constant::text() const {
    if (type == ValueType::Bool) return v[0] != 0 ? "true" : "false";
    if (!is_vector(type)) return fmt::format("{}", v[0]);
    std::string s = "[";
    for (int i = 0; i < component_count(type); ++i) s += fmt::format("{}{}", i ? ", " : "", v[static_cast<std::size_t>(i)]);
    return s + "]";
}

}  // namespace fg
