void fg_fractal_kifs(vec3 p, float scale, vec3 offset, vec3 axis, float pre_angle_deg, float angle_deg, int iterations,
                     float bias, OUT(float) distance, OUT(vec4) trap)
{
    vec3 z = p;
    float dr = 1.0;
    float len = length(axis);
    vec3 a = len > FG_TINY ? axis / len : vec3(0.0, 0.0, 1.0);
    float pre = pre_angle_deg * FG_PI / 180.0;
    float post = angle_deg * FG_PI / 180.0;
    float r2 = dot(z, z);
    trap = vec4(abs(z.x), abs(z.y), abs(z.z), r2);
    for (int i = 0; i < iterations; i++) {
        fg_count_fractal_iteration();
        if (r2 > 1e4) break;
        z = fg_rotate_axis(z, a, pre);
        // The tetrahedron's three symmetry planes: reflect into the side of the (1, 1, 1) vertex.
        if (z.x + z.y < 0.0) z = vec3(-z.y, -z.x, z.z);
        if (z.x + z.z < 0.0) z = vec3(-z.z, z.y, -z.x);
        if (z.y + z.z < 0.0) z = vec3(z.x, -z.z, -z.y);
        z = fg_rotate_axis(z, a, post);
        z = z * scale - offset * (scale - 1.0);
        // Capped below float32's overflow: an infinite dr would make bias * dr NaN at bias 0.
        dr = min(fg_conservative_dr(dr, bias, dr * abs(scale)), 1e30);
        r2 = dot(z, z);
        trap = min(trap, vec4(abs(z.x), abs(z.y), abs(z.z), r2));
    }
    // The last level's tetrahedron (vertices (1,1,1), (-1,-1,1), (1,-1,-1), (-1,1,-1)), brought back by dr.
    float t = max(max(-z.x - z.y - z.z, z.x + z.y - z.z), max(-z.x + z.y + z.z, z.x - z.y + z.z));
    distance = (t - 1.0) / (sqrt(3.0) * max(dr, FG_TINY));
}
