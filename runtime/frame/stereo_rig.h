#pragma once
// From a head pose to the three views the frame graph renders: the left and right eyes, and the
// centre eye that stereo reprojection marches (the head's position, a frustum covering both eyes
// plus a margin, and the same angular pixel size).
#include <cstdint>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace fg {

struct HeadPose {
    glm::dvec3 position{0.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};   // -z forward, +y up, +x right (OpenXR's convention)
};

// Frustum edges as tangents of their angles: left and down are negative for a centred view.
struct Fov {
    double left = -1.0, right = 1.0, down = -1.0, up = 1.0;
    static Fov symmetric(double horizontal_deg, double aspect);    // aspect = width / height
    static Fov from_angles(double left, double right, double down, double up);  // radians, as OpenXR
};

struct View {
    glm::dvec3 origin{0.0};
    glm::dvec3 right{1.0, 0.0, 0.0}, up{0.0, 1.0, 0.0}, forward{0.0, 0.0, -1.0};
    Fov fov;
    std::uint32_t width = 0, height = 0;

    glm::dvec3 ray(double u, double v) const;   // unit direction through (u, v) in [0, 1]^2, v down
};

struct StereoViews {
    View left, right, centre;
    double pixel_tan = 0.0;        // tangent-plane size of one full-resolution pixel (x)
    double pixel_half_diagonal = 0.0;
    double ipd = 0.0;              // scene units
    glm::dvec2 jitter{0.0};        // the eyes' sub-pixel jitter (StereoSettings::jitter)
};

struct StereoSettings {
    std::uint32_t width = 256, height = 256;   // per eye
    double ipd_m = 0.064;                      // metres
    double world_scale = 1.0;                  // scene units per metre
    double centre_margin_tan = 0.05;           // the centre eye sees this far past both eyes
    // Sub-pixel jitter of both eyes' pixel grids, in pixels (x right, y down): each frame of an
    // accumulated or temporally filtered picture samples other points inside its pixels. The eyes
    // share one phase, so stereo reuse still finds the same points in both; the centre eye of stereo
    // reprojection, which only proves space empty, is never jittered. Panoramas take it too
    // (projection.h), every view alike.
    glm::dvec2 jitter{0.0};
    // Temporal upsampling: each eye's output is `upscale` times `width` x `height` (FrameSettings::
    // output_width), and a marched pixel exactly `upscale` output pixels: the marched frustum
    // reaches past the output's, right and down, where the output size is no multiple of it.
    double upscale = 1.0;
    std::uint32_t output_width = 0, output_height = 0;
    // A thin lens (depth of field, offline samples): each eye looks from `lens` (scene units, x
    // right, y up) off its centre on the lens, its frustum sheared so that the plane `focus` ahead
    // stays where it was. None where focus is 0.
    glm::dvec2 lens{0.0};
    double focus = 0.0;
};

// The frustum of `fov` moved by `pixels` (x right, y down) of a `width` x `height` image: every
// pass that makes or projects rays through a view's frustum then agrees on the jittered rays.
Fov jittered(const Fov& fov, glm::dvec2 pixels, std::uint32_t width, std::uint32_t height);

struct FrameSettings;

// The eyes' sizes of the frames `f` marches, and temporal upsampling's output (above).
void set_marched_size(StereoSettings& s, const FrameSettings& f);

StereoViews make_stereo_views(const HeadPose& head, const Fov& left, const Fov& right, const StereoSettings& s);

// A head looking from `position` at `target`.
HeadPose look_at(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up = {0.0, 1.0, 0.0});

}  // namespace fg
