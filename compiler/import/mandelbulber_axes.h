#pragma once
// Mandelbulber's axes and rotations in the graph's terms. Its z axis is up, the graph's y is: a
// point (x, y, z) there is (x, z, -y) here (both right-handed). Its rotations are given as three
// angles in degrees, each a turn about one of its axes; the matrix multiplies them in a fixed order
// (the formula names which), and a turn by a positive angle is counter-clockwise looking down the
// axis.
#include <glm/glm.hpp>

namespace fg {

glm::dvec3 to_graph_axes(const glm::dvec3& v);

// Rz(z) * Ry(y) * Rx(x), the angles in degrees, about Mandelbulber's axes: the point is turned
// about x first.
glm::dmat3 rotation_zyx(double z_deg, double y_deg, double x_deg);

// A rotation about Mandelbulber's axes as stage.rotate takes it: an axis in graph axes and an
// angle in degrees (0 for none).
struct AxisAngle {
    glm::dvec3 axis{0.0, 1.0, 0.0};
    double degrees = 0.0;
};
AxisAngle graph_axis_angle(const glm::dmat3& rotation);
// The same turn kept in Mandelbulber's axes.
AxisAngle axis_angle(const glm::dmat3& rotation);

}  // namespace fg
