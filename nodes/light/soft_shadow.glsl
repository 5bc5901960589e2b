void fg_light_soft_shadow(vec3 position, vec3 normal, vec3 light_dir, float light_distance, float angle, float start,
                          float max_distance, int steps,
                          OUT(float) shadow)
{
    float slope = tan(angle * (FG_PI / 180.0));
    vec3 origin = position + normal * start;
    // The narrowest passage so far, in light radii: 1 clear of the light's disc, 0 at its centre,
    // -1 fully hidden.
    float passage = 1.0;
    float t = start;
    float end = min(max_distance, light_distance);
    for (int i = 0; i < steps && t < end && passage > -1.0; i++) {
        float h = fg_scene_distance(origin + light_dir * t);
        passage = min(passage, h / (slope * t));
        // Inside the surface h is negative: step on by the smallest step, deeper into the shadow.
        t += max(h, start);
    }
    float r = clamp(passage, -1.0, 1.0);
    shadow = 0.25 * (1.0 + r) * (1.0 + r) * (2.0 - r);
}
