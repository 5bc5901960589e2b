void fg_fractal_mandelbox(vec3 p, float scale, float min_radius, float fixed_radius, float fold_limit,
                          int iterations, float bias, OUT(float) distance, OUT(vec4) trap, OUT(float) escape)
{
    vec3 z = p;
    float dr = 1.0;
    // Squared radii with a floor: the sphere fold divides by them.
    float min_r2 = max(min_radius * min_radius, 1e-12);
    float fixed_r2 = max(fixed_radius * fixed_radius, min_r2);
    float r2 = dot(z, z);
    trap = vec4(abs(z.x), abs(z.y), abs(z.z), r2);
    float r2_last = r2;
    int i = 0;
    for (; i < iterations; i++) {
        fg_count_fractal_iteration();
        if (r2 > 1e4) break;
        r2_last = r2;
        // Box fold: reflect each coordinate that leaves [-fold_limit, fold_limit].
        z = clamp(z, -fold_limit, fold_limit) * 2.0 - z;
        // Sphere fold: invert the shell between min and fixed radius, scale up the inside.
        r2 = dot(z, z);
        float k = 1.0;
        if (r2 < min_r2) k = fixed_r2 / min_r2;
        else if (r2 < fixed_r2) k = fixed_r2 / r2;
        z = z * (k * scale) + p;
        // Capped below float32's overflow: an infinite dr would make bias * dr NaN at bias 0.
        dr = min(fg_conservative_dr(dr, bias, dr * k * abs(scale) + 1.0), 1e30);
        r2 = dot(z, z);
        trap = min(trap, vec4(abs(z.x), abs(z.y), abs(z.z), r2));
    }
    distance = sqrt(r2) / dr;
    escape = fg_escape_share(i, iterations, r2_last, r2, 1e4);
}
