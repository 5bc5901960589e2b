#pragma once
// The texels of a lat-long image as environment.glsl maps it (v = 0 straight up, u = 0.5 looking
// down -z, growing towards +x): each texel's centre direction and its row's solid angle, and its
// half-float values read as numbers.
#include <cmath>
#include <cstdint>
#include <numbers>

#include <Imath/half.h>
#include <glm/glm.hpp>

namespace fg {

inline glm::dvec3 lat_long_direction(std::uint32_t i, std::uint32_t j, std::uint32_t w, std::uint32_t h) {
    const double pi = std::numbers::pi;
    const double theta = (j + 0.5) * pi / h, phi = ((i + 0.5) / w - 0.5) * 2.0 * pi;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

// The solid angle of each texel of row j.
inline double lat_long_solid_angle(std::uint32_t j, std::uint32_t w, std::uint32_t h) {
    const double pi = std::numbers::pi;
    return (2.0 * pi / w) * (std::cos(j * pi / h) - std::cos((j + 1) * pi / h));
}

inline double half_value(std::uint16_t bits) {
    Imath::half v;
    v.setBits(bits);
    return static_cast<double>(v);
}

}  // namespace fg
