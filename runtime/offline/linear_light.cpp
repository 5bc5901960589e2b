#include "linear_light.h"

#include <algorithm>
#include <cmath>

namespace fg {

namespace {
double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double linear_to_srgb(double c) { return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }
}  // namespace

const std::array<double, 256>& srgb8_linear_table() {
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i) t[static_cast<std::size_t>(i)] = srgb_to_linear(i / 255.0);
        return t;
    }();
    return table;
}

std::uint8_t linear_to_srgb8(double linear) {
    return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(linear_to_srgb(linear), 0.0, 1.0)));
}

}  // namespace fg
