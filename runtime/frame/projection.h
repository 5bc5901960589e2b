#pragma once
// How pixels become rays: the headset's perspective frusta, or the panoramas of offline renders
// (equirectangular mono, and omni-directional stereo as 360-degree video players expect it:
// top-bottom equirectangular, each column's eye on the circle of the interpupillary distance).
// The shaders' fg_ray_origin / fg_ray_dir (shaders/common.glsl) and projection_ray here are the
// same formulas; the CPU side is the reference tests check the GPU against.
#include <string>

#include "stereo_rig.h"

namespace fg {

enum class Projection {
    Perspective = 0,   // per-eye frusta (as in the headset); the numbers are FG_PROJECTION_* in GLSL
    Equirect = 1,      // one 360x180-degree image from the head's centre
    Ods = 2,           // omni-directional stereo: an equirectangular image per eye
};

const char* projection_name(Projection p);
bool parse_projection(const std::string& s, Projection& out);
// Panoramas of one eye only (equirect) render the centre view.
inline bool is_mono(Projection p) { return p == Projection::Equirect; }

struct Ray {
    glm::dvec3 origin, dir;
};

// The ray through (u, v) in [0, 1]^2 (v down) of `view`; side is -1 for the left eye, +1 for the
// right, 0 for the centre; ipd in scene units (ODS only).
Ray projection_ray(Projection p, const View& view, double side, double ipd, double u, double v);

// The views of a panorama: every view at the head's centre with the head's axes (ODS offsets the
// eyes per column in the shader), width x height each, and the angular size of a pixel.
StereoViews make_panorama_views(const HeadPose& head, const StereoSettings& s);

}  // namespace fg
