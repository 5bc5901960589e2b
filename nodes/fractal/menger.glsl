void fg_fractal_menger(vec3 p, float scale, vec3 offset, vec3 axis, float angle_deg, int iterations, float bias,
                       OUT(float) distance, OUT(vec4) trap)
{
    vec3 z = p;
    float dr = 1.0;
    float len = length(axis);
    vec3 a = len > FG_TINY ? axis / len : vec3(0.0, 1.0, 0.0);
    float angle = angle_deg * FG_PI / 180.0;
    float r2 = dot(z, z);
    trap = vec4(abs(z.x), abs(z.y), abs(z.z), r2);
    for (int i = 0; i < iterations; i++) {
        fg_count_fractal_iteration();
        if (r2 > 1e4) break;
        // Fold into the wedge x >= y >= z >= 0: abs and sorting are reflections, so distances survive.
        z = abs(z);
        if (z.x < z.y) z = vec3(z.y, z.x, z.z);
        if (z.x < z.z) z = vec3(z.z, z.y, z.x);
        if (z.y < z.z) z = vec3(z.x, z.z, z.y);
        z = fg_rotate_axis(z, a, angle);
        // Scale about the corner cube; the z fold brings the edge cubes back (Knighty's Menger IFS).
        z = z * scale - offset * (scale - 1.0);
        if (z.z < -0.5 * offset.z * (scale - 1.0)) z.z += offset.z * (scale - 1.0);
        // Capped below float32's overflow: an infinite dr would make bias * dr NaN at bias 0.
        dr = min(fg_conservative_dr(dr, bias, dr * abs(scale)), 1e30);
        r2 = dot(z, z);
        trap = min(trap, vec4(abs(z.x), abs(z.y), abs(z.z), r2));
    }
    // The level-n cube: exact box distance, brought back by the accumulated scale.
    vec3 q = abs(z) - vec3(1.0);
    distance = (length(max(q, vec3(0.0))) + min(max(q.x, max(q.y, q.z)), 0.0)) / max(dr, FG_TINY);
}
