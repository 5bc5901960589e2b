void fg_fractal_fold_iterate(vec3 p, bool mirror, bool sort, float box_limit, float min_radius, float fixed_radius, vec3 axis,
                             float angle_deg, float scale, vec3 offset, float add_point, float radius, int iterations,
                             float bailout, float bias, OUT(float) distance, OUT(vec4) trap, OUT(float) escape)
{
    vec3 z = p;
    float dr = 1.0;
    float len = length(axis);
    vec3 a = len > FG_TINY ? axis / len : vec3(0.0, 0.0, 1.0);
    float angle = angle_deg * FG_PI / 180.0;
    float min_r2 = max(min_radius * min_radius, 1e-12);
    float fixed_r2 = fixed_radius * fixed_radius;
    float bail2 = bailout * bailout;
    float r2 = dot(z, z);
    trap = vec4(abs(z.x), abs(z.y), abs(z.z), r2);
    float r2_last = r2;
    int i = 0;
    for (; i < iterations; i++) {
        fg_count_fractal_iteration();
        if (r2 > bail2) break;
        r2_last = r2;
        // Each stage is a fold (a piecewise isometry) or a uniform scale, so dr tracks them exactly.
        if (mirror) z = abs(z);
        // Sorting the coordinates (x >= y >= z) is three plane reflections: the octahedral fold.
        if (sort) {
            if (z.x < z.y) z = vec3(z.y, z.x, z.z);
            if (z.x < z.z) z = vec3(z.z, z.y, z.x);
            if (z.y < z.z) z = vec3(z.x, z.z, z.y);
        }
        if (box_limit > 0.0) z = clamp(z, -box_limit, box_limit) * 2.0 - z;
        float k = 1.0;
        if (fixed_r2 > min_r2) {
            float zr2 = dot(z, z);
            if (zr2 < min_r2) k = fixed_r2 / min_r2;
            else if (zr2 < fixed_r2) k = fixed_r2 / zr2;
        }
        z = fg_rotate_axis(z * k, a, angle);
        z = z * scale + offset + p * add_point;
        // Capped below float32's overflow: an infinite dr would make bias * dr NaN at bias 0.
        dr = min(fg_conservative_dr(dr, bias, dr * k * abs(scale) + abs(add_point)), 1e30);
        r2 = dot(z, z);
        trap = min(trap, vec4(abs(z.x), abs(z.y), abs(z.z), r2));
    }
    distance = (sqrt(r2) - radius) / max(dr, FG_TINY);
    escape = fg_escape_share(i, iterations, r2_last, r2, bail2);
}
