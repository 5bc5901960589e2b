#pragma once
// Makes node bodies written in GLSL compile as C++ in double precision (the CPU twin). Included by
// the generated file that #includes every nodes/**/*.glsl inside namespace fg::glsl with
// `#define float double`. Rules the bodies follow so this works: no swizzles beyond .x .y .z .w,
// no 'f' literal suffixes, outputs through OUT(type), float literals written with a decimal point.
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

namespace fg::glsl {

using namespace glm;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using ivec2 = glm::ivec2;
using ivec3 = glm::ivec3;
using mat2 = glm::dmat2;
using mat3 = glm::dmat3;
using mat4 = glm::dmat4;

// GLSL's scalar forms that GLM spells differently or leaves to <cmath>.
inline double atan(double y, double x) { return std::atan2(y, x); }
inline double mod(double x, double y) { return x - y * std::floor(x / y); }
inline double inversesqrt(double x) { return 1.0 / std::sqrt(x); }

// Shade-context nodes call the scene's distance function; the CPU evaluator installs it.
double fg_scene_distance(vec3 p);

}  // namespace fg::glsl

#define OUT(T) T&
#define INOUT(T) T&
