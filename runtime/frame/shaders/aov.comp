//! pass: aov
//! needs: surface trap
//! when: always
//! include: post_effects.glsl
//! include-after-scene: environment.glsl
//! include-after-scene: shading.glsl
//! include-after-scene: volume.glsl
// The terms of one eye's picture for a compositor (OpenEXR output, docs/camera-path.md): the HDR
// beauty before the tone map, camera depth and world position, normal, AO, albedo, the diffuse
// factor, the orbit trap, the specular reflectance, the shadow, the mirror bounce's colour and the
// light through glass. Runs only when an offline render asks for them; it shades each hit once more
// with the shade pass's own functions, so the beauty is the picture's colour.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform readonly image2D fg_depth;
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 4, r32f) uniform readonly image2D fg_glow;
#endif
layout(set = 0, binding = 5, rgba16f) uniform writeonly image2D fg_beauty;     // rgb linear HDR, exposed; a 1
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D fg_position;   // xyz world, w camera depth (metres)
layout(set = 0, binding = 7, rgba16f) uniform writeonly image2D fg_normal;     // xyz unit normal, w AO
layout(set = 0, binding = 8, rgba16f) uniform writeonly image2D fg_albedo;     // rgb albedo, w diffuse factor
layout(set = 0, binding = 9, rgba16f) uniform writeonly image2D fg_trap;       // the fractal's orbit trap
#if defined(FG_HAS_SHADOW) || defined(FG_HAS_SPECULAR)
#define FG_AOV_LIGHT 1
layout(set = 0, binding = 10, rgba16f) uniform writeonly image2D fg_light;     // rgb specular, w shadow
#endif
#ifdef FG_HAS_REFLECTION
layout(set = 0, binding = 11, rgba16f) uniform writeonly image2D fg_reflection;   // rgb the mirror bounce's colour
#endif
#ifdef FG_HAS_REFRACTION
layout(set = 0, binding = 18, rgba16f) uniform writeonly image2D fg_refraction;   // rgb the light through glass
#endif
layout(push_constant) uniform FgAovPush { AovPush pc; };

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(fg_frame.eye_size);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    fg_shading_pixel = pixel;
    vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
    vec3 ro = fg_ray_origin(pc.view, uv);
    vec3 rd = fg_ray_dir(pc.view, uv);
    float t = imageLoad(fg_depth, pixel).x;
    float closest = 0.0;
#ifdef FG_HAS_GLOW
    closest = imageLoad(fg_glow, pixel).x;
#endif
    vec3 scattered = vec3(0.0);
#ifdef FG_HAS_FOG
    scattered = fg_fog_light(ro, rd, t);
#endif
    if (t < 0.0) {
        vec3 background = fg_background(rd);
#ifdef FG_HAS_VOLUME
        background = fg_through_volume(background, ro, rd, t);
#endif
        vec3 beauty = fg_post_effects(background, pixel, size, ro, rd, t, closest, scattered);
        imageStore(fg_beauty, pixel, vec4(beauty * fg_scene.exposure, 1.0));
        // A miss is infinitely far (as Nuke and Blender read depth); it has no surface.
        imageStore(fg_position, pixel, vec4(0.0, 0.0, 0.0, uintBitsToFloat(0x7f800000u)));
        imageStore(fg_normal, pixel, vec4(0.0));
        imageStore(fg_albedo, pixel, vec4(0.0));
        imageStore(fg_trap, pixel, vec4(0.0));
#ifdef FG_AOV_LIGHT
        imageStore(fg_light, pixel, vec4(0.0));
#endif
#ifdef FG_HAS_REFLECTION
        imageStore(fg_reflection, pixel, vec4(0.0));
#endif
#ifdef FG_HAS_REFRACTION
        imageStore(fg_refraction, pixel, vec4(0.0));
#endif
        return;
    }
    vec3 p = ro + rd * t;
    // The normal is written even where the picture needs none; the shading sees what shade saw.
    vec3 n = fg_surface_normal(p, t);
#ifdef FG_HAS_NORMALS
    FgShading s = fg_shade_hit(p, rd, n, t);
#else
    FgShading s = fg_shade_hit(p, rd, vec3(0.0, 1.0, 0.0), t);
#endif
    vec3 shaded = s.color;
#ifdef FG_HAS_VOLUME
    shaded = fg_through_volume(shaded, ro, rd, t);
#endif
    vec3 beauty = fg_post_effects(shaded, pixel, size, ro, rd, t, closest, scattered);
    imageStore(fg_beauty, pixel, vec4(beauty * fg_scene.exposure, 1.0));
    // Camera depth: along the view axis in perspective, along the ray in a panorama; metres.
    GpuView v = fg_frame.views[pc.view];
    float along = fg_projection() == FG_PROJECTION_PERSPECTIVE ? t * dot(rd, v.forward.xyz) : t;
#ifdef FG_DOUBLE_SCENE
    vec3 world = vec3(fg_anchor() + dvec3(p));
#else
    vec3 world = p;
#endif
    imageStore(fg_position, pixel, vec4(world, along / fg_frame.world_scale));
    imageStore(fg_normal, pixel, vec4(n, s.ao));
    imageStore(fg_albedo, pixel, vec4(s.albedo, s.diffuse));
    imageStore(fg_trap, pixel, fg_scene_trap(p));
#ifdef FG_AOV_LIGHT
    imageStore(fg_light, pixel, vec4(s.specular, s.shadow));
#endif
#ifdef FG_HAS_REFLECTION
    imageStore(fg_reflection, pixel, vec4(s.reflected, 0.0));
#endif
#ifdef FG_HAS_REFRACTION
    imageStore(fg_refraction, pixel, vec4(s.refracted, 0.0));
#endif
}
