// The shading of a hit, shared by the shade pass (the picture) and the AOV pass (its terms for a
// compositor), so the two cannot drift apart. Pasted after the scene's functions
// (`//! include-after-scene:`), which it calls.

vec3 fg_background(vec3 rd)
{
#ifdef FG_HAS_ENVIRONMENT
    return fg_environment_radiance(rd);
#elif defined(FG_HAS_BACKGROUND_GRADIENT)
    return mix(fg_scene.bg_bottom.rgb, fg_scene.bg_top.rgb, clamp(0.5 + 0.5 * rd.y, 0.0, 1.0));
#else
    return fg_scene.bg_top.rgb;
#endif
}

// A gradient can vanish (inside a body, where the field is flat, or below float's resolution):
// normalize(0) is NaN, and adding 1e-20 does not help where denormals flush to zero (1e-40).
vec3 fg_safe_normalize(vec3 g)
{
    float len2 = dot(g, g);
    return len2 > 1e-30 ? g * inversesqrt(len2) : vec3(0.0, 1.0, 0.0);
}

vec3 fg_normal_at(vec3 p, float h)
{
    if (FG_NORMAL_TAPS >= 6) {
        vec2 e = vec2(h, 0.0);
        return fg_safe_normalize(vec3(fg_scene_distance(p + e.xyy) - fg_scene_distance(p - e.xyy),
                                      fg_scene_distance(p + e.yxy) - fg_scene_distance(p - e.yxy),
                                      fg_scene_distance(p + e.yyx) - fg_scene_distance(p - e.yyx)));
    }
    // Tetrahedral taps: four evaluations instead of six.
    vec2 k = vec2(1.0, -1.0);
    return fg_safe_normalize(k.xyy * fg_scene_distance(p + k.xyy * h) + k.yyx * fg_scene_distance(p + k.yyx * h) +
                             k.yxy * fg_scene_distance(p + k.yxy * h) + k.xxx * fg_scene_distance(p + k.xxx * h));
}

// The normal at a hit at distance t. The tap distance follows the output pixel's footprint, so
// normals are as sharp as the image shown, at any march resolution. Its floor (an eye inside the fractal has t = 0) scales with the viewer
// (world scale in world_scale: a scene at 1e-6 is smaller than a fixed 1e-6) and stays above
// float's spacing at p.
vec3 fg_surface_normal(vec3 p, float t)
{
    float floor_h = max(1e-6 * fg_frame.world_scale, 1e-6 * length(p));
    return fg_normal_at(p, max(fg_detail_tan() * t, floor_h));
}

struct FgShading {
    vec3 color;      // linear, before post effects and the tone map
    vec3 albedo;
    float diffuse;   // the light's diffuse factor
    float ao;
    float shadow;    // how much of the light reaches the point
    vec3 specular;   // the specular reflectance towards the camera
    vec3 reflected;  // the colour the mirror bounce and the environment in the specular lobe add
    vec3 refracted;  // the colour the light through a glass body adds
    FgSurface surface;   // the graph's outputs it came from
};

#ifdef FG_HAS_LIGHTS
// Auxiliary light i seen from the point x: the unit direction towards it, how far it is, and the
// light it brings there (a point light's falls off with the square of its distance).
vec3 fg_auxiliary_towards(uint i, vec3 x, out vec3 towards, out float distance)
{
    vec4 light = fg_scene.auxiliary_light[i];
    vec3 radiance = fg_scene.auxiliary_color[i].rgb;
    towards = light.xyz;
    distance = FG_DIRECTIONAL_LIGHT_DISTANCE;
    if (light.w > 0.5) {
#ifdef FG_DOUBLE_SCENE
        vec3 offset = vec3(dvec3(light.xyz) - fg_anchor()) - x;
#else
        vec3 offset = light.xyz - x;
#endif
        distance = max(length(offset), 1e-20);
        towards = offset / distance;
        radiance /= distance * distance;
    }
    return radiance;
}

// What auxiliary light i adds at the hit p seen along rd: the graph's diffuse, shadow and
// specular evaluated towards it.
vec3 fg_auxiliary_light(uint i, vec3 p, vec3 rd, vec3 n, vec3 albedo)
{
    vec3 towards;
    float distance;
    vec3 radiance = fg_auxiliary_towards(i, p, towards, distance);
    FgLightTerms l = fg_scene_light_terms(p, -rd, n, towards, distance);
    return radiance * (albedo * l.diffuse + l.specular) * l.shadow;
}
#endif

#if defined(FG_HAS_REFLECTION) || defined(FG_HAS_ENVIRONMENT) || defined(FG_HAS_FOG) || defined(FG_HAS_REFRACTION)
// A ray from `origin`, t along the eye's ray, leaving along dir: true, with the point it meets and
// its distance from the eye's origin, where it meets the surface by the same rule as the eye's rays
// (the pixel's cone grown over the whole path).
bool fg_march_on(vec3 origin, vec3 dir, float t, out vec3 q, out float total)
{
    float footprint = FG_EPSILON * fg_detail_tan();
    vec2 range = fg_bounds_interval(origin, dir, 0.0);
    float along = max(range.x, 0.0);
    for (int i = 0; i < FG_MAX_STEPS && along <= range.y; i++) {
        q = origin + dir * along;
        total = t + along;
        float d = float(fg_scene_distance(q)) * FG_STEP_SCALE;
        if (d < footprint * FG_STEP_FRACTION * total) return true;
        along += d;
    }
    return false;
}

// How far from a surface t from the eye a ray leaving it starts, so that it does not meet that
// surface again at once.
float fg_surface_offset(float t)
{
    float footprint = FG_EPSILON * fg_detail_tan();
    return 2.0 * footprint * t + 1e-6 * fg_frame.world_scale;
}

// The same from the hit p with normal n: it starts just above the surface.
bool fg_march_from_hit(vec3 p, vec3 n, vec3 dir, float t, out vec3 q, out float total)
{
    return fg_march_on(p + n * fg_surface_offset(t), dir, t, q, total);
}
#endif

#ifdef FG_HAS_FOG
// Henyey-Greenstein's phase of the fog (anisotropy fog_height.w) for light arriving from `towards`
// and leaving along rd.
float fg_fog_phase(vec3 towards, vec3 rd)
{
    float g = fg_scene.fog_height.w;
    return (1.0 - g * g) / (4.0 * FG_FLOAT_PI * pow(max(1.0 + g * g - 2.0 * g * dot(towards, rd), 1e-6), 1.5));
}

// How far along the ray from ro along rd the fog has taken the share u of the light (1 - T = u):
// the optical depth -ln(1 - u), inverted.
float fg_fog_at_share(vec3 ro, vec3 rd, float u)
{
    float depth = -log(1.0 - u);
    float s = depth / max(fg_scene.fog_density, 1e-30);
    if (fg_scene.fog_height.x > 0.0) {
        float a = fg_fog_density_at(ro), x = fg_scene.fog_height.x * rd.y;
        s = abs(x * depth / a) < 1e-4 ? depth / a : -log(max(1.0 - x * depth / a, 1e-30)) / x;
    }
    return s;
}

#ifdef FG_HAS_LIGHTS
// Points a frame integrates a point light's scattering over.
const int FG_FOG_LIGHT_POINTS = 16;

// What the fog scatters towards the eye of auxiliary light i along the ray from ro along rd over
// `far`, unshadowed. A directional light's is share * phase * (1 - T), as the main light's. A point
// light's falls off along the ray as 1 / d^2: seen by the angle from the ray's point nearest it
// (equiangular, Kulla and Fajardo 2012) the fall-off cancels against the stretch of the ray, and
// what is left, density * T * phase, is smooth, so a few evenly spread angles take the integral.
vec3 fg_fog_auxiliary(uint i, vec3 ro, vec3 rd, float far, float opaque)
{
    float share = fg_scene.fog_height.z;
    vec3 towards;
    float distance;
    vec3 radiance = fg_auxiliary_towards(i, ro, towards, distance);
    if (fg_scene.auxiliary_light[i].w <= 0.5) return radiance * (share * fg_fog_phase(towards, rd) * opaque);
    vec3 offset = towards * distance;
    float nearest = dot(offset, rd);
    float h = max(length(offset - rd * nearest), 1e-6 * fg_frame.world_scale);
    float first = atan(-nearest, h), last = atan(far - nearest, h);
    float spacing = (last - first) / float(FG_FOG_LIGHT_POINTS);
    vec3 light = vec3(0.0);
    for (int k = 0; k < FG_FOG_LIGHT_POINTS; k++) {
        float s = nearest + h * tan(first + (float(k) + 0.5) * spacing);
        vec3 x = ro + rd * s;
        vec3 brought = fg_auxiliary_towards(i, x, towards, distance);
        // I / d^2 ds = I / h dtheta: the radiance times d^2 / h.
        float scattering = fg_fog_density_at(x) * exp(-fg_fog_depth(ro, rd, s));
        light += brought * (distance * distance / h * spacing * scattering * share * fg_fog_phase(towards, rd));
    }
    return light;
}
#endif

// The light the fog scatters towards the eye along the ray from ro along rd over t (a miss: the far
// limit), its share fog_height.z of each light. With a constant share, the scattering density times
// the transmittance integrates to 1 - T over the ray, whatever the density's profile: a frame takes
// that for the main light and the auxiliary lights, unshadowed (fg_fog_auxiliary), and for the
// environment its harmonics weighted by the phase's (fg_environment_scattered). While samples
// accumulate, each sample takes one point of the ray, drawn in proportion to that integrand (the
// optical depth inverted), and marches from it towards each light and one direction of the sky: the
// mean converges to the shadowed integral, light shafts through the fractal's holes included.
vec3 fg_fog_light(vec3 ro, vec3 rd, float t)
{
    float share = fg_scene.fog_height.z;
    if (share <= 0.0) return vec3(0.0);
    float far = t < 0.0 ? fg_scene.far_limit : t;
    float opaque = 1.0 - exp(-fg_fog_depth(ro, rd, far));
    vec3 light = fg_scene.light_color.rgb * share * fg_fog_phase(fg_scene.light_dir.xyz, rd) * opaque;
    vec3 towards;
    float distance;
    if (fg_frame.area_light.z == 0.0) {
#ifdef FG_HAS_LIGHTS
        for (uint i = 0u; i < fg_scene.auxiliary_lights; i++) light += fg_fog_auxiliary(i, ro, rd, far, opaque);
#endif
#ifdef FG_HAS_ENVIRONMENT
        light += fg_environment_scattered(rd, fg_scene.fog_height.w) * (share * opaque);
#endif
        return light;
    }
    float s = min(fg_fog_at_share(ro, rd, fg_sample_square(2u).x * opaque), far);
    vec3 x = ro + rd * s;
    vec3 q;
    float total;
    vec3 scattered = fg_march_on(x, fg_scene.light_dir.xyz, s, q, total) ? vec3(0.0) : light;
#ifdef FG_HAS_LIGHTS
    for (uint i = 0u; i < fg_scene.auxiliary_lights; i++) {
        vec3 radiance = fg_auxiliary_towards(i, x, towards, distance);
        // Only what lies between the point and the light shadows it.
        if (!fg_march_on(x, towards, s, q, total) || total - s > distance)
            scattered += radiance * (share * fg_fog_phase(towards, rd) * opaque);
    }
#endif
#ifdef FG_HAS_ENVIRONMENT
    // One direction of the sky, drawn by its brightness, and a march towards it.
    vec3 sky = fg_environment_sample(fg_sample_square(3u));
    float pdf = fg_environment_pdf(sky);
    if (pdf > 0.0 && !fg_march_on(x, sky, s, q, total))
        scattered += fg_environment_radiance(sky) * (share * fg_fog_phase(sky, rd) * opaque / pdf);
#endif
    return scattered;
}
#endif

#ifdef FG_HAS_ENVIRONMENT
// Two tangents completing unit n to an orthonormal frame, without a branch on its direction (Duff
// et al. 2017).
void fg_tangent_frame(vec3 n, out vec3 tangent, out vec3 bitangent)
{
    float side = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (side + n.z);
    float b = n.x * n.y * a;
    tangent = vec3(1.0 + side * n.x * n.x * a, side * b, -side * n.x);
    bitangent = vec3(b, side + n.y * n.y * a, -n.y);
}

// What the environment reflects off a white diffuse surface at the hit p (t along the eye's ray)
// with normal n. In a frame: its irradiance over pi, occluded by the graph's ao. While samples
// accumulate: one direction a sample, drawn half the time by the image's brightness and half the
// time by the cosine, weighted by both densities (one-sample multiple importance sampling, Veach
// 1997), and shadowed by marching the fractal towards it; their mean converges to the integral.
vec3 fg_environment_light(vec3 p, vec3 n, float t, float ao)
{
    if (fg_frame.area_light.z == 0.0) return fg_environment_irradiance(n) * ao;
    vec2 xi = fg_sample_square(1u);
    vec3 dir;
    if (xi.x < 0.5) {
        dir = fg_environment_sample(vec2(2.0 * xi.x, xi.y));
    } else {
        // Cosine-weighted about n (Malley): a disc point lifted onto the hemisphere.
        vec3 tangent, bitangent;
        fg_tangent_frame(n, tangent, bitangent);
        float r = sqrt(2.0 * xi.x - 1.0), phi = 2.0 * FG_FLOAT_PI * xi.y;
        dir = tangent * (r * cos(phi)) + bitangent * (r * sin(phi)) + n * sqrt(max(2.0 - 2.0 * xi.x, 0.0));
    }
    float cosine = dot(n, dir);
    if (cosine <= 0.0) return vec3(0.0);
    vec3 q;
    float total;
    if (fg_march_from_hit(p, n, dir, t, q, total)) return vec3(0.0);
    float pdf = 0.5 * fg_environment_pdf(dir) + 0.5 * cosine / FG_FLOAT_PI;
    return fg_environment_radiance(dir) * (cosine / FG_FLOAT_PI / pdf);
}
#endif

#if defined(FG_HAS_ENVIRONMENT) && defined(FG_OUT_SPECULAR_COLOR)
// A normal of GGX alpha `alpha` about n drawn as seen from v (the distribution of visible normals,
// Heitz 2018): the view stretched to alpha 1, a point of the projected half disc, unstretched.
vec3 fg_ggx_visible_normal(vec3 v, vec3 n, float alpha, vec2 xi)
{
    vec3 tangent, bitangent;
    fg_tangent_frame(n, tangent, bitangent);
    vec3 stretched = normalize(vec3(alpha * dot(v, tangent), alpha * dot(v, bitangent), dot(v, n)));
    float across = stretched.x * stretched.x + stretched.y * stretched.y;
    vec3 t1 = across > 0.0 ? vec3(-stretched.y, stretched.x, 0.0) * inversesqrt(across) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(stretched, t1);
    float r = sqrt(xi.x), phi = 2.0 * FG_FLOAT_PI * xi.y;
    float p1 = r * cos(phi), p2 = r * sin(phi);
    float s = 0.5 * (1.0 + stretched.z);
    p2 = (1.0 - s) * sqrt(max(1.0 - p1 * p1, 0.0)) + s * p2;
    vec3 m = p1 * t1 + p2 * t2 + sqrt(max(1.0 - p1 * p1 - p2 * p2, 0.0)) * stretched;
    vec3 local = normalize(vec3(alpha * m.x, alpha * m.y, max(m.z, 0.0)));
    return tangent * local.x + bitangent * local.y + n * local.z;
}

// Steps the march of a reflection's cone takes in a frame.
const int FG_GLOSS_STEPS = 32;

// The share of a cone a passage leaves open, the passage in cone radii from its axis: 1 clear of
// the cone, 0 through its axis, -1 fully hidden (light.soft_shadow's profile).
float fg_cone_open(float passage)
{
    float r = clamp(passage, -1.0, 1.0);
    return 0.25 * (1.0 + r) * (1.0 + r) * (2.0 - r);
}

// In a frame: the share of the lobe's cone about the mirror direction dir that the scene leaves
// open, by the narrowest passage a march along dir finds. The cone holds half the lobe (half angle
// 2 atan(alpha)), between 1 and 45 degrees. What the hit's own tangent plane hides of it is left
// out: the lobe's reflectance (the table) already counts only what is above the surface.
float fg_gloss_open(vec3 p, vec3 n, vec3 dir, float t, float alpha)
{
    float slope = clamp(2.0 * alpha / max(1.0 - alpha * alpha, 1e-3), 0.02, 1.0);
    float start = fg_surface_offset(t);
    vec3 origin = p + n * start;
    float along = start, end = fg_bounds_interval(origin, dir, 0.0).y;
    float passage = 1.0;
    // How far the march has gone on at the surface: a distance that never goes negative (Mandelbox,
    // KIFS, Kleinian) stays near 0 inside the set, and this stands in for the depth it cannot give.
    float at_surface = 0.0;
    for (int i = 0; i < FG_GLOSS_STEPS && along < end && passage > -1.0; i++) {
        float h = float(fg_scene_distance(origin + dir * along)) * FG_STEP_SCALE;
        at_surface = h >= 0.0 && h < (1.0 / 256.0) * slope * along ? at_surface + start : 0.0;
        passage = min(passage, (h - at_surface) / (slope * along));
        along += max(h, start);
    }
    return min(fg_cone_open(passage) / fg_cone_open(dot(dir, n) / slope), 1.0);
}

// What the graph's specular lobe (specular_color, roughness) reflects of the environment at the hit
// p, t along rd, normal n. In a frame: the split sum, the image prefiltered by the lobe about the
// mirror direction times the lobe's reflectance of a white sky, occluded by the cone the scene
// leaves open about the mirror direction and by the graph's ao. While
// samples accumulate: one direction a sample, drawn from the lobe's visible normals or (up to half
// the time, the rougher the lobe the more often) by the image's brightness, weighted by both
// densities, and shadowed by marching the fractal towards it.
vec3 fg_environment_gloss(vec3 p, vec3 rd, vec3 n, float t, FgSurface s, float ao)
{
    vec3 v = -rd;
    float nv = max(dot(n, v), 1e-4);
    float roughness = clamp(s.roughness, 0.0, 1.0);
    if (fg_frame.area_light.z == 0.0) {
        vec2 scale = fg_environment_gloss_scale(nv, roughness);
        vec3 mirror = reflect(rd, n);
        float open = fg_gloss_open(p, n, mirror, t, roughness * roughness);
        return fg_environment_prefiltered(mirror, roughness) * (s.specular_color * scale.x + scale.y) * (open * ao);
    }
    float alpha = max(roughness * roughness, 1e-3), a2 = alpha * alpha;
    // A near mirror's lobe is narrower than any texel's worth of the image: only its own normals.
    float by_image = 0.5 * smoothstep(0.05, 0.3, roughness);
    vec2 xi = fg_sample_square(10u);
    vec3 dir = xi.x < by_image ? fg_environment_sample(vec2(xi.x / by_image, xi.y))
                               : reflect(rd, fg_ggx_visible_normal(v, n, alpha, vec2((xi.x - by_image) / (1.0 - by_image), xi.y)));
    float nl = dot(n, dir);
    if (nl <= 0.0) return vec3(0.0);
    vec3 h = normalize(v + dir);
    float nh = max(dot(n, h), 0.0), vh = max(dot(v, h), 0.0);
    float q = nh * nh * (a2 - 1.0) + 1.0;
    float distribution = a2 / (FG_FLOAT_PI * q * q);
    float visibility = 0.5 / max(nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2), 1e-6);
    // The visible normals' density of dir: G1(v) D / (4 n.v).
    float masking = 2.0 * nv / (nv + sqrt(a2 + (1.0 - a2) * nv * nv));
    float pdf = by_image * fg_environment_pdf(dir) + (1.0 - by_image) * masking * distribution / (4.0 * nv);
    vec3 q_hit;
    float total;
    if (fg_march_from_hit(p, n, dir, t, q_hit, total)) return vec3(0.0);
    vec3 fresnel = s.specular_color + (vec3(1.0) - s.specular_color) * pow(1.0 - vh, 5.0);
    return fg_environment_radiance(dir) * fresnel * (distribution * visibility * nl / pdf);
}
#endif

// Shades the hit p, t along rd, with normal n by its direct terms: the graph's surface outputs,
// the lights, the environment, fake lighting, emission; no mirror bounce.
FgShading fg_shade_direct(vec3 p, vec3 rd, vec3 n, float t)
{
    FgSurface s = fg_scene_surface(p, -rd, n);
#ifdef FG_OUT_DIFFUSE
    float diffuse = s.diffuse;
#else
    float diffuse = max(dot(n, fg_scene.light_dir.xyz), 0.0);
#endif
    // Each optional term exists only when the pack lists its effect: a scene without SSS, rim or
    // emission carries no code for them.
#ifdef FG_HAS_AO
    float ao = s.ao;
#else
    float ao = 1.0;
#endif
#ifdef FG_HAS_SHADOW
    float shadow = s.shadow;
#else
    float shadow = 1.0;
#endif
#ifdef FG_HAS_SPECULAR
    vec3 specular = s.specular;
#else
    vec3 specular = vec3(0.0);
#endif
    // The light reaches the point by its shadow: diffusely scattered by the albedo, and reflected
    // by the specular lobe.
    vec3 reflected = vec3(0.0);
    vec3 color = s.albedo * (fg_scene.ambient.rgb * ao + fg_scene.light_color.rgb * diffuse * shadow) +
                 fg_scene.light_color.rgb * specular * shadow;
#ifdef FG_HAS_LIGHTS
    for (uint i = 0u; i < fg_scene.auxiliary_lights; i++) color += fg_auxiliary_light(i, p, rd, n, s.albedo);
#endif
#ifdef FG_HAS_ENVIRONMENT
    color += s.albedo * fg_environment_light(p, n, t, ao);
#ifdef FG_OUT_SPECULAR_COLOR
    reflected = fg_environment_gloss(p, rd, n, t, s, ao);
    color += reflected;
#endif
#endif
#ifdef FG_HAS_SSS
    color += s.sss * fg_scene.sss_color.rgb * s.albedo;
#endif
#ifdef FG_HAS_RIM
    color += s.rim * fg_scene.rim_color.rgb;
#endif
#ifdef FG_HAS_EMISSION
    color += s.emission;
#endif
    return FgShading(color, s.albedo, diffuse, ao, shadow, specular, reflected, vec3(0.0), s);
}

#ifdef FG_HAS_REFLECTION
// The scene in the mirror direction from the hit p, t along rd: what each bounce meets shaded by its
// direct terms, and where that reflects too, reflected again, up to FG_REFLECTION_BOUNCES bounces; a
// miss sees the background. It hits by the same rule as the eye's rays, the pixel's cone grown over
// the whole path.
vec3 fg_reflected_light(vec3 p, vec3 rd, vec3 n, float t)
{
    vec3 light = vec3(0.0), weight = vec3(1.0);
    for (int bounce = 0; bounce < FG_REFLECTION_BOUNCES; bounce++) {
        vec3 dir = reflect(rd, n);
        vec3 q;
        float total;
        if (!fg_march_from_hit(p, n, dir, t, q, total)) return light + weight * fg_background(dir);
        vec3 m = fg_surface_normal(q, total);
        FgShading met = fg_shade_direct(q, dir, m, total);
        light += weight * met.color;
        weight *= met.surface.reflection;
        if (weight == vec3(0.0)) break;
        p = q;
        rd = dir;
        n = m;
        t = total;
    }
    return light;
}
#endif

#ifdef FG_HAS_REFRACTION
// Marches through glass a ray takes at most: one a body it crosses, one more each internal bounce.
const int FG_GLASS_SEGMENTS = 6;

// A ray inside a body from `origin` (t travelled from the eye) along dir: true, with the point just
// inside where the body ends, where the distance (negative inside) comes back within the pixel's
// cone grown over the whole path, the rule the eye's rays meet surfaces by.
bool fg_march_inside(vec3 origin, vec3 dir, float t, out vec3 q)
{
    float footprint = FG_EPSILON * fg_detail_tan();
    float along = 0.0;
    for (int i = 0; i < FG_MAX_STEPS; i++) {
        q = origin + dir * along;
        float d = -float(fg_scene_distance(q)) * FG_STEP_SCALE;
        if (d < footprint * FG_STEP_FRACTION * (t + along)) return true;
        along += d;
    }
    return false;
}

// The light that comes through glass from the hit p (t along rd, normal n, the graph's outputs
// there): the ray bends in by Snell's law, loses exp(-absorption * length) inside, and at the far
// side bends out or, past the critical angle, reflects back inside. In a frame the exit passes on
// its Fresnel transmission; while samples accumulate it reflects inside as often as Fresnel says and
// passes on all of the rest, so the mean counts every internal path. Out of the body the ray takes
// the direct terms of what it meets, and goes on through it where that is glass too, or the
// background.
vec3 fg_refracted_light(vec3 p, vec3 rd, vec3 n, float t, FgSurface surface)
{
    bool sampling = fg_frame.area_light.z != 0.0;
    vec3 light = vec3(0.0), weight = vec3(1.0);
    float ior = surface.ior;
    vec3 absorption = surface.absorption;
    vec3 dir = refract(rd, n, 1.0 / ior);
    vec3 from = p;                              // where the ray entered or last reflected
    vec3 at = p - n * fg_surface_offset(t);     // where its march starts, below that surface
    for (int segment = 0; segment < FG_GLASS_SEGMENTS; segment++) {
        vec3 q;
        if (!fg_march_inside(at, dir, t, q)) return light;
        // The length inside, surface to surface: `from` lies short of its surface outside and q
        // short of its own inside, by the same rule, so the two errors cancel (the march's length
        // would miss the start's offset: 1.1 % more light through the refraction test's red ball).
        float inside = distance(from, q);
        weight *= exp(-absorption * inside);
        t += inside;
        vec3 m = fg_surface_normal(q, t);   // outwards, at the far side
        vec3 out_dir = refract(dir, -m, ior);
        float reflectance = float(fg_fresnel_dielectric(dot(dir, m), 1.0 / ior));
        bool back = out_dir == vec3(0.0);   // total internal reflection
        if (!back && sampling) back = fg_sample_square(4u + uint(segment)).x < reflectance;
        if (back) {
            dir = reflect(dir, m);
            from = q;
            at = q - m * fg_surface_offset(t);
            continue;
        }
        if (!sampling) weight *= 1.0 - reflectance;
        vec3 hit;
        float total;
        if (!fg_march_from_hit(q, m, out_dir, t, hit, total)) return light + weight * fg_background(out_dir);
        vec3 normal = fg_surface_normal(hit, total);
        FgShading met = fg_shade_direct(hit, out_dir, normal, total);
        light += weight * met.color;
        if (met.surface.transmission == vec3(0.0)) return light;
        // Glass again: into it.
        weight *= met.surface.transmission;
        ior = met.surface.ior;
        absorption = met.surface.absorption;
        dir = refract(out_dir, normal, 1.0 / ior);
        from = hit;
        at = hit - normal * fg_surface_offset(total);
        t = total;
    }
    return light;
}
#endif

// Shades the hit p, t along rd, with normal n: its direct terms, and where the graph reflects, the
// mirror bounce weighted by its reflectance; where it refracts, the light through the body.
FgShading fg_shade_hit(vec3 p, vec3 rd, vec3 n, float t)
{
    FgShading s = fg_shade_direct(p, rd, n, t);
#ifdef FG_HAS_REFLECTION
    // Only where the graph reflects: one graph often holds a mirror and surfaces that are not.
    if (s.surface.reflection != vec3(0.0)) {
        vec3 bounce = s.surface.reflection * fg_reflected_light(p, rd, n, t);
        s.reflected += bounce;
        s.color += bounce;
    }
#endif
#ifdef FG_HAS_REFRACTION
    if (s.surface.transmission != vec3(0.0)) {
        s.refracted = s.surface.transmission * fg_refracted_light(p, rd, n, t, s.surface);
        s.color += s.refracted;
    }
#endif
    return s;
}
