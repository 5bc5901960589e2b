#include "mandelbulber_axes.h"

#include <algorithm>
#include <cmath>

namespace fg {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A matrix from its rows (glm stores columns).
glm::dmat3 rows(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) { return glm::transpose(glm::dmat3(a, b, c)); }

glm::dmat3 turn_x(double rad) {
    const double c = std::cos(rad), s = std::sin(rad);
    return rows({1, 0, 0}, {0, c, -s}, {0, s, c});
}
glm::dmat3 turn_y(double rad) {
    const double c = std::cos(rad), s = std::sin(rad);
    return rows({c, 0, s}, {0, 1, 0}, {-s, 0, c});
}
glm::dmat3 turn_z(double rad) {
    const double c = std::cos(rad), s = std::sin(rad);
    return rows({c, -s, 0}, {s, c, 0}, {0, 0, 1});
}

}  // namespace

glm::dvec3 to_graph_axes(const glm::dvec3& v) { return {v.x, v.z, -v.y}; }

glm::dmat3 rotation_zyx(double z_deg, double y_deg, double x_deg) {
    const double k = kPi / 180.0;
    return turn_z(z_deg * k) * turn_y(y_deg * k) * turn_x(x_deg * k);
}

AxisAngle graph_axis_angle(const glm::dmat3& rotation) {
    // In graph axes the same turn is P R P^T, P the change of axes.
    const glm::dmat3 p = rows({1, 0, 0}, {0, 0, 1}, {0, -1, 0});
    return axis_angle(p * rotation * glm::transpose(p));
}

AxisAngle axis_angle(const glm::dmat3& r) {
    // The skew part is 2 sin(angle) times the axis, the trace 1 + 2 cos(angle); near a half turn
    // the skew part vanishes and the symmetric part's largest column gives the axis.
    glm::dvec3 axis(r[1][2] - r[2][1], r[2][0] - r[0][2], r[0][1] - r[1][0]);   // glm: r[column][row]
    const double angle = std::atan2(0.5 * glm::length(axis), 0.5 * (r[0][0] + r[1][1] + r[2][2] - 1.0));
    if (angle < 1e-12) return {};
    if (glm::length(axis) < 1e-6) {
        const glm::dmat3 s = (r + glm::dmat3(1.0)) * 0.5;   // = axis axis^T at a half turn
        int k = 0;
        for (int i = 1; i < 3; ++i)
            if (s[i][i] > s[k][k]) k = i;
        axis = s[k];
    }
    return {glm::normalize(axis), angle * 180.0 / kPi};
}

}  // namespace fg
