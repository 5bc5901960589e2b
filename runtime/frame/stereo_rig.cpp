#include "stereo_rig.h"

#include "frame_settings.h"

#include <algorithm>
#include <cmath>

namespace fg {

Fov Fov::symmetric(double horizontal_deg, double aspect) {
    double tx = std::tan(glm::radians(horizontal_deg) * 0.5);
    double ty = tx / aspect;
    return {-tx, tx, -ty, ty};
}

Fov Fov::from_angles(double l, double r, double d, double u) {
    return {std::tan(l), std::tan(r), std::tan(d), std::tan(u)};
}

glm::dvec3 View::ray(double u, double v) const {
    double tx = fov.left + (fov.right - fov.left) * u;
    double ty = fov.up + (fov.down - fov.up) * v;
    return glm::normalize(forward + tx * right + ty * up);
}

HeadPose look_at(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up) {
    glm::dvec3 f = glm::normalize(target - position);
    glm::dvec3 r = glm::cross(f, up);
    if (glm::length(r) < 1e-9) r = glm::cross(f, glm::dvec3(0.0, 0.0, 1.0));
    r = glm::normalize(r);
    glm::dvec3 u = glm::cross(r, f);
    // Columns: x = right, y = up, z = backwards (the head looks down -z).
    glm::dmat3 m(r, u, -f);
    return {position, glm::quat_cast(m)};
}

namespace {

// The marched frustum of an output frustum `fov` under temporal upsampling (StereoSettings::upscale).
Fov marched_fov(const Fov& fov, const StereoSettings& s) {
    if (s.upscale <= 1.0 || !s.output_width || !s.output_height) return fov;
    const double wide = s.width * s.upscale / s.output_width, tall = s.height * s.upscale / s.output_height;
    return {fov.left, fov.left + (fov.right - fov.left) * wide, fov.up - (fov.up - fov.down) * tall, fov.up};
}

}  // namespace

void set_marched_size(StereoSettings& s, const FrameSettings& f) {
    s.width = f.width;
    s.height = f.height;
    s.upscale = f.taa_upscale();
    s.output_width = f.shown_width();
    s.output_height = f.shown_height();
}

StereoViews make_stereo_views(const HeadPose& head, const Fov& shown_left, const Fov& shown_right, const StereoSettings& s) {
    const Fov left = marched_fov(shown_left, s), right = marched_fov(shown_right, s);
    StereoViews out;
    glm::dmat3 basis = glm::mat3_cast(head.orientation);
    glm::dvec3 r = basis[0], u = basis[1], f = -basis[2];
    out.ipd = s.ipd_m * s.world_scale;
    auto eye = [&](const Fov& fov, double side) {
        View v;
        v.origin = head.position + r * (side * out.ipd * 0.5);
        v.right = r;
        v.up = u;
        v.forward = f;
        v.fov = fov;
        v.width = s.width;
        v.height = s.height;
        return v;
    };
    out.left = eye(left, -1.0);
    out.right = eye(right, 1.0);
    double dx = (left.right - left.left) / s.width;
    double dy = (left.up - left.down) / s.height;
    out.pixel_tan = dx;
    out.pixel_half_diagonal = 0.5 * std::sqrt(dx * dx + dy * dy);

    // The centre eye: both frusta and a margin, whole pixels of the same size.
    View c = eye(left, 0.0);
    double l = std::min(left.left, right.left) - s.centre_margin_tan;
    double rr = std::max(left.right, right.right) + s.centre_margin_tan;
    double d = std::min(left.down, right.down);
    double up = std::max(left.up, right.up);
    c.width = static_cast<std::uint32_t>(std::ceil((rr - l) / dx));
    c.height = static_cast<std::uint32_t>(std::ceil((up - d) / dy));
    double cx = 0.5 * (l + rr), cy = 0.5 * (d + up);
    c.fov = {cx - 0.5 * c.width * dx, cx + 0.5 * c.width * dx, cy - 0.5 * c.height * dy, cy + 0.5 * c.height * dy};
    out.centre = c;
    if (s.focus > 0.0)
        for (View* v : {&out.left, &out.right}) {
            v->origin += r * s.lens.x + u * s.lens.y;
            const double dx = s.lens.x / s.focus, dy = s.lens.y / s.focus;
            v->fov = {v->fov.left - dx, v->fov.right - dx, v->fov.down - dy, v->fov.up - dy};
        }
    out.left.fov = jittered(out.left.fov, s.jitter, s.width, s.height);
    out.right.fov = jittered(out.right.fov, s.jitter, s.width, s.height);
    out.jitter = s.jitter;
    return out;
}

Fov jittered(const Fov& fov, glm::dvec2 pixels, std::uint32_t width, std::uint32_t height) {
    double dx = pixels.x * (fov.right - fov.left) / width;
    double dy = pixels.y * (fov.up - fov.down) / height;   // image y runs down, the tangent up
    return {fov.left + dx, fov.right + dx, fov.down - dy, fov.up - dy};
}

}  // namespace fg
