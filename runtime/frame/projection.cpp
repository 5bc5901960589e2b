#include "projection.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "frame/shaders/gpu_interface.h"

namespace fg {

const char* projection_name(Projection p) {
    switch (p) {
        case Projection::Perspective: return "perspective";
        case Projection::Equirect: return "equirect";
        case Projection::Ods: return "ods";
    }
    return "?";
}

bool parse_projection(const std::string& s, Projection& out) {
    for (auto p : {Projection::Perspective, Projection::Equirect, Projection::Ods})
        if (s == projection_name(p)) {
            out = p;
            return true;
        }
    return false;
}

Ray projection_ray(Projection p, const View& view, double side, double ipd, double u, double v) {
    if (p == Projection::Perspective) return {view.origin, view.ray(u, v)};
    double lon = (u - 0.5) * 2.0 * std::numbers::pi, lat = (0.5 - v) * std::numbers::pi;
    glm::dvec3 dir = std::cos(lat) * (std::sin(lon) * view.right + std::cos(lon) * view.forward) + std::sin(lat) * view.up;
    glm::dvec3 origin = view.origin;
    if (p == Projection::Ods) {
        // Closer together towards the poles, as the shaders' fg_ods_separation.
        double x = std::clamp((std::abs(lat) - FG_ODS_FADE_START) / FG_ODS_FADE_WIDTH, 0.0, 1.0);
        double separation = 1.0 - x * x * (3.0 - 2.0 * x);
        origin += side * 0.5 * ipd * separation * (std::cos(lon) * view.right - std::sin(lon) * view.forward);
    }
    return {origin, dir};
}

StereoViews make_panorama_views(const HeadPose& head, const StereoSettings& s) {
    StereoViews out;
    glm::dmat3 basis = glm::mat3_cast(head.orientation);
    View v;
    v.origin = head.position;
    v.right = basis[0];
    v.up = basis[1];
    v.forward = -basis[2];
    v.width = s.width;
    v.height = s.height;
    out.left = out.right = out.centre = v;
    out.ipd = s.ipd_m * s.world_scale;
    // A pixel spans 2 pi / width of longitude (less away from the equator) and pi / height of
    // latitude. A cone must cover every direction of its footprint: going along the meridian
    // and then the parallel reaches any of them, so the sum of the half-spans bounds the angle
    // (fg_cone_tan takes its tangent, larger still).
    double dlon = 2.0 * std::numbers::pi / s.width, dlat = std::numbers::pi / s.height;
    out.pixel_tan = dlon;
    out.pixel_half_diagonal = 0.5 * (dlon + dlat);
    out.jitter = s.jitter;   // the shaders move each pixel's point by it (fg_panorama_uv)
    return out;
}

}  // namespace fg
