void fg_light_soft_shadow(vec3 position, vec3 normal, vec3 light_dir, float light_distance, float angle, float start,
                          float max_distance, int steps, bool area, vec3 light_sample,
                          OUT(float) shadow)
{
    float slope = tan(angle * (FG_PI / 180.0));
    vec3 origin = position + normal * start;
    float t = start;
    float end = min(max_distance, light_distance);
    if (area && light_sample.z > 0.0) {
        // Samples accumulate: one sharp ray towards this sample's point of the light's disc (radius
        // `slope` one unit along the light). It is blocked where it enters the surface, or passes
        // within a 32nd of the light's radius of it: a cone that thin, half hidden, is the sharp
        // ray's limit of the profile below, and a distance that never goes negative still stops it.
        vec3 side = normalize(cross(light_dir, abs(light_dir.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
        vec3 towards = normalize(light_dir + slope * (light_sample.x * side + light_sample.y * cross(light_dir, side)));
        shadow = 1.0;
        for (int i = 0; i < steps && t < end; i++) {
            float h = fg_scene_distance(origin + towards * t);
            if (h < (1.0 / 256.0) * slope * t) {
                shadow = 0.0;
                break;
            }
            t += max(h, start);
        }
        return;
    }
    // The narrowest passage so far, in light radii: 1 clear of the light's disc, 0 at its centre,
    // -1 fully hidden.
    float passage = 1.0;
    // How far the ray has gone on at the surface: a distance that never goes negative (Mandelbox,
    // KIFS, Kleinian) stays near 0 inside the set, and this stands in for the depth it cannot give.
    float at_surface = 0.0;
    for (int i = 0; i < steps && t < end && passage > -1.0; i++) {
        float h = fg_scene_distance(origin + light_dir * t);
        at_surface = h >= 0.0 && h < (1.0 / 256.0) * slope * t ? at_surface + start : 0.0;
        passage = min(passage, (h - at_surface) / (slope * t));
        // Inside the surface h is negative: step on by the smallest step, deeper into the shadow.
        t += max(h, start);
    }
    float r = clamp(passage, -1.0, 1.0);
    shadow = 0.25 * (1.0 + r) * (1.0 + r) * (2.0 - r);
}
