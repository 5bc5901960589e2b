void fg_light_marched_ao(vec3 position, vec3 normal, float radius, int rays, float start, int steps, float strength,
                         OUT(float) ao)
{
    // A frame about the normal without a branch on its direction (Duff et al. 2017).
    float side = normal.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (side + normal.z);
    float b = normal.x * normal.y * a;
    vec3 tangent = vec3(1.0 + side * normal.x * normal.x * a, side * b, -side * normal.x);
    vec3 bitangent = vec3(b, side + normal.y * normal.y * a, -normal.y);
    // Each cone's share of the hemisphere, 2 pi / rays of solid angle: cos of its half-angle.
    float cones = float(max(rays, 1));
    float c = 1.0 - 1.0 / cones;
    float slope = sqrt(max(1.0 - c * c, 0.0)) / max(c, 1e-3);
    vec3 origin = position + normal * start;
    float open = 0.0;
    for (int i = 0; i < rays; i++) {
        float u = (float(i) + 0.5) / float(rays);
        float phi = float(i) * 2.39996322972865;   // the golden angle
        float r = sqrt(u);
        vec3 direction = tangent * (r * cos(phi)) + bitangent * (r * sin(phi)) + normal * sqrt(1.0 - u);
        // How narrowly the cone's axis passed the surface, in cone half-widths (light.soft_shadow's march).
        // A distance that never goes negative stays near 0 inside: how far the axis goes on at the
        // surface stands in for the depth (as in light.soft_shadow).
        float passage = 1.0;
        float t = start;
        float at_surface = 0.0;
        for (int s = 0; s < steps && t < radius && passage > -1.0; s++) {
            float h = fg_scene_distance(origin + direction * t);
            at_surface = h >= 0.0 && h < (1.0 / 256.0) * slope * t ? at_surface + start : 0.0;
            passage = min(passage, (h - at_surface) / (slope * t));
            t += max(h, start);
        }
        float q = clamp(passage, -1.0, 1.0);
        open += 0.25 * (1.0 + q) * (1.0 + q) * (2.0 - q);
    }
    // No rays: no occlusion (the term dropped).
    ao = rays > 0 ? clamp(1.0 - strength * (1.0 - open / cones), 0.0, 1.0) : 1.0;
}
