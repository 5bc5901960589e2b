#include "gpu_uniforms.h"

#include <algorithm>

#include "lens_mask.h"

namespace fg {

namespace {
vec4 v4(const glm::dvec3& v, double w = 0.0) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), static_cast<float>(w)};
}
vec3 v3(const glm::dvec3& v) { return glm::vec3(v); }
GpuView gpu_view(const View& v, bool lens_mask) {
    GpuView g{v4(v.origin), v4(v.right), v4(v.up), v4(v.forward),
              {static_cast<float>(v.fov.left), static_cast<float>(v.fov.right), static_cast<float>(v.fov.down),
               static_cast<float>(v.fov.up)},
              {0.5f, 0.5f}, {0.0f, 0.0f}};
    if (lens_mask) {
        LensEllipse e = lens_ellipse(v);
        g.lens_centre = {static_cast<float>(e.centre_u), static_cast<float>(e.centre_v)};
        g.lens_radii = {static_cast<float>(e.radius_u), static_cast<float>(e.radius_v)};
    }
    return g;
}
}  // namespace

GpuFrame make_gpu_frame(const StereoViews& views, const FrameSettings& settings, double time, double world_scale,
                        std::uint32_t frame_index) {
    GpuFrame f{};
    f.views[FG_VIEW_LEFT] = gpu_view(views.left, settings.lens_mask);
    f.views[FG_VIEW_RIGHT] = gpu_view(views.right, settings.lens_mask);
    f.views[FG_VIEW_CENTRE] = gpu_view(views.centre, false);   // the centre eye serves both lenses
    const glm::dvec3 anchor = views.centre.origin;
    const glm::dvec3 hi = glm::dvec3(glm::vec3(anchor));
    f.anchor_hi = v4(hi);
    f.anchor_lo = v4(anchor - hi);
    if (settings.camera_relative) {
        // Float keeps the few digits that separate the eyes only once the camera is subtracted.
        f.views[FG_VIEW_LEFT].origin = v4(views.left.origin - anchor);
        f.views[FG_VIEW_RIGHT].origin = v4(views.right.origin - anchor);
        f.views[FG_VIEW_CENTRE].origin = v4(views.centre.origin - anchor);
    }
    f.eye_size = {views.left.width, views.left.height};
    f.centre_size = {views.centre.width, views.centre.height};
    f.frame_index = frame_index;
    f.cone_levels = settings.cone_levels;
    f.projection = static_cast<uint>(settings.projection);
    f.fovea_radius = static_cast<float>(std::max(settings.foveation, 0.0));
    f.fovea_blend = static_cast<float>(settings.foveation_blend);
    f.seconds = static_cast<float>(time);
    f.world_scale = static_cast<float>(world_scale);
    f.ipd = static_cast<float>(views.ipd);
    f.pixel_cone_tan = static_cast<float>(views.pixel_half_diagonal);
    f.pixel_tan = static_cast<float>(views.pixel_tan);
    f.detail_cone = static_cast<float>(views.pixel_half_diagonal * settings.detail_scale);
    f.jitter = {static_cast<float>(views.jitter.x), static_cast<float>(views.jitter.y), 0.0f, 0.0f};
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
    if (s.fog) {
        g.fog_color = v3(s.fog->color);
        g.fog_density = static_cast<float>(s.fog->density);
        g.fog_height = {static_cast<float>(s.fog->height_falloff), static_cast<float>(s.fog->height),
                        static_cast<float>(s.fog->scatter), static_cast<float>(s.fog->anisotropy)};
    }
    if (s.glow) {
        g.glow_color = v3(s.glow->color * s.glow->intensity);
        g.glow_falloff = static_cast<float>(s.glow->falloff);
    }
    g.bounds_centre = v3(s.bounds_center);
    g.bounds_radius = static_cast<float>(s.bounds_radius);
    g.bounds_centre_lo = v3(s.bounds_center - glm::dvec3(glm::vec3(s.bounds_center)));
    g.exposure = static_cast<float>(s.exposure);
    g.far_limit = static_cast<float>(s.max_distance);
    g.vignette = s.vignette ? static_cast<float>(s.vignette->strength) : 0.0f;
    static_assert(std::size(g.auxiliary_light) == SceneSettings::Light::kMaxAuxiliary);
    g.auxiliary_lights = static_cast<uint>(s.light.auxiliary.size());
    for (std::size_t i = 0; i < s.light.auxiliary.size(); ++i) {
        const auto& light = s.light.auxiliary[i];
        g.auxiliary_light[i] = light.position ? glm::vec4(v3(*light.position), 1.0f) : glm::vec4(v3(light.direction), 0.0f);
        g.auxiliary_color[i] = v4(light.color);
    }
    if (s.environment)
        g.environment = glm::vec4(v3(s.environment->color * s.environment->intensity),
                                  static_cast<float>(glm::radians(s.environment->rotation_deg)));
    return g;
}

}  // namespace fg
