void fg_light_soft_shadow(vec3 position, vec3 normal, vec3 light_dir, float light_distance, float angle, float start,
                          float max_distance, int steps, bool area, int rays, vec3 light_sample,
                          OUT(float) shadow)
{
    float slope = tan(angle * (FG_PI / 180.0));
    vec3 origin = position + normal * start;
    float t = start;
    float end = min(max_distance, light_distance);
    if (area && light_sample.z > 0.0) {
        // Samples accumulate: `rays` sharp rays towards points of the light's disc (radius `slope`
        // one unit along the light): a lattice that covers the unit square evenly, ray j at
        // (j / rays, j / golden ratio), shifted by this sample's point and mapped onto the disc. A
        // ray is blocked where it enters the surface, or passes within a 256th of the light's
        // radius of it: a cone that thin, half hidden, is the sharp ray's limit of the profile
        // below, and a distance that never goes negative still stops it.
        vec3 side = normalize(cross(light_dir, abs(light_dir.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
        vec3 up = cross(light_dir, side);
        int n = max(rays, 1);
        float seen = 0.0;
        for (int j = 0; j < n; j++) {
            vec2 lattice = vec2(float(j) / float(n), fract(float(j) * 0.618033989));
            vec2 disc = fg_concentric_disc(fract(vec2(light_sample.x, light_sample.y) + lattice));
            vec3 towards = normalize(light_dir + slope * (disc.x * side + disc.y * up));
            float visible = 1.0;
            float along = start;
            for (int i = 0; i < steps && along < end; i++) {
                float h = fg_scene_distance(origin + towards * along);
                if (h < (1.0 / 256.0) * slope * along) {
                    visible = 0.0;
                    break;
                }
                along += max(h, start);
            }
            seen += visible;
        }
        shadow = seen / float(n);
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
