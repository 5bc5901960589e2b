#include "gpu_uniforms.h"

#include <algorithm>

#include "lens_mask.h"

namespace fg {

namespace {
std::array<float, 4> v4(const glm::dvec3& v, double w = 0.0) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), static_cast<float>(w)};
}
GpuView gpu_view(const View& v, bool lens_mask) {
    GpuView g{v4(v.origin), v4(v.right), v4(v.up), v4(v.forward),
              {static_cast<float>(v.fov.left), static_cast<float>(v.fov.right), static_cast<float>(v.fov.down),
               static_cast<float>(v.fov.up)},
              {0.5f, 0.5f, 0.0f, 0.0f}};
    if (lens_mask) {
        LensEllipse e = lens_ellipse(v);
        g.lens = {static_cast<float>(e.centre_u), static_cast<float>(e.centre_v), static_cast<float>(e.radius_u),
                  static_cast<float>(e.radius_v)};
    }
    return g;
}
}  // namespace

GpuFrame make_gpu_frame(const StereoViews& views, const FrameSettings& settings, double time, double world_scale,
                        std::uint32_t frame_index) {
    GpuFrame f{};
    f.views[0] = gpu_view(views.left, settings.lens_mask);
    f.views[1] = gpu_view(views.right, settings.lens_mask);
    f.views[2] = gpu_view(views.centre, false);   // the centre eye serves both lenses
    const glm::dvec3 anchor = views.centre.origin;
    const glm::dvec3 hi = glm::dvec3(glm::vec3(anchor));
    f.anchor_hi = v4(hi);
    f.anchor_lo = v4(anchor - hi);
    if (settings.camera_relative) {
        // Float keeps the few digits that separate the eyes only once the camera is subtracted.
        f.views[0].origin = v4(views.left.origin - anchor);
        f.views[1].origin = v4(views.right.origin - anchor);
        f.views[2].origin = v4(views.centre.origin - anchor);
    }
    f.size = {views.left.width, views.left.height, views.centre.width, views.centre.height};
    f.info = {frame_index, settings.cone_levels, 0, 0};
    f.foveation = {static_cast<float>(std::max(settings.foveation, 0.0)), static_cast<float>(settings.foveation_blend),
                   0.0f, 0.0f};
    f.time = {static_cast<float>(time), static_cast<float>(world_scale), static_cast<float>(views.ipd), 0.0f};
    f.pixel = {static_cast<float>(views.pixel_half_diagonal), static_cast<float>(views.pixel_tan), 0.0f, 0.0f};
    return f;
}

GpuScene make_gpu_scene(const SceneSettings& s) {
    GpuScene g{};
    g.light_dir = v4(s.light.direction);
    g.light_color = v4(s.light.color);
    g.ambient = v4(s.light.ambient);
    g.sss_color = v4(s.light.sss_color);
    g.rim_color = v4(s.light.rim_color);
    g.albedo = v4(s.albedo);
    g.bg_top = v4(s.background.top);
    g.bg_bottom = v4(s.background.bottom);
    if (s.fog) g.fog = v4(s.fog->color, s.fog->density);
    if (s.glow) g.glow = v4(s.glow->color * s.glow->intensity, s.glow->falloff);
    g.bounds = v4(s.bounds_center, s.bounds_radius);
    g.bounds_lo = v4(s.bounds_center - glm::dvec3(glm::vec3(s.bounds_center)));
    g.misc = {static_cast<float>(s.exposure), static_cast<float>(s.max_distance),
              s.vignette ? static_cast<float>(s.vignette->strength) : 0.0f,
              s.foveation ? static_cast<float>(s.foveation->inner_radius) : 1.0f};
    g.misc2 = {s.foveation ? static_cast<float>(s.foveation->blend) : 0.0f, 0.0f, 0.0f, 0.0f};
    return g;
}

}  // namespace fg
