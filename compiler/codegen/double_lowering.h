#pragma once
// Precision "double" (scene.precision, fgc compile --precision): node GLSL rewritten so the scene
// evaluates in double on the GPU. Types become their double forms (float -> double, vecN -> dvecN,
// matN -> dmatN), float literals get the lf suffix (0.1 is not 0.1f), and the transcendental
// functions GLSL has only for float go to nodes/double_math.glsl (fg_d_sin ...). Comments are
// copied unchanged, and no line is added or removed, so the source map still points at the node.
#include <string>
#include <string_view>
#include <vector>

#include "common/value_type.h"

namespace fg {

std::string lower_to_double(std::string_view glsl);

// Functions a body calls that have no double form (floatBitsToInt, dFdx, noise1, tanh ...), once
// each in order of appearance: the compiler reports them against the node. Empty when it lowers.
std::vector<std::string> functions_without_double(std::string_view glsl);

// The componentwise dvec2, dvec3 and dvec4 forms of the double math functions, as GLSL.
std::string double_math_vector_forms();

// double, dvec3 ... for a value type; int and bool stay as they are.
std::string double_type_name(ValueType t);

}  // namespace fg
