#pragma once
// The value types that flow along graph edges, shared by the node library, the IR, the CPU twin
// and code generation.
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace fg {

enum class ValueType { Float, Int, Bool, Vec2, Vec3, Vec4 };

std::string_view type_name(ValueType t);                 // "float", "vec3": also the GLSL spelling
std::optional<ValueType> parse_type(std::string_view s);
int component_count(ValueType t);                        // 1 for scalars
bool is_vector(ValueType t);
bool is_float_like(ValueType t);                         // float or a float vector: has a tangent
ValueType float_vector(int components);                  // 1 -> Float, 3 -> Vec3

// A constant: a literal from the graph, a parameter default, or a folded node output.
// Ints and bools are held exactly as doubles (integers below 2^53).
struct Constant {
    ValueType type = ValueType::Float;
    std::array<double, 4> v{0, 0, 0, 0};

    static Constant scalar(ValueType t, double x);
    static Constant vector(ValueType t, std::array<double, 4> xs);
    double max_abs() const;
    std::string glsl() const;    // a GLSL expression of this value: "vec3(1.0, 0.5, 0.0)"
    std::string text() const;    // human form for messages: "[1, 0.5, 0]"
    bool operator==(const Constant&) const = default;
};

}  // namespace fg
