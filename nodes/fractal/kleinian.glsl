void fg_fractal_kleinian(vec3 p, vec3 box_size, float inversion, vec3 shift, float sheet_radius, int iterations,
                         float bias, OUT(float) distance, OUT(vec4) trap)
{
    vec3 z = p;
    float dr = 1.0;
    float r2 = dot(z, z);
    trap = vec4(abs(z.x), abs(z.y), abs(z.z), r2);
    for (int i = 0; i < iterations; i++) {
        fg_count_fractal_iteration();
        // Box fold, then inversion in the sphere of squared radius `inversion` for points inside it.
        z = clamp(z, -box_size, box_size) * 2.0 - z;
        r2 = max(dot(z, z), 1e-12);
        float k = max(inversion / r2, 1.0);
        z = z * k + shift;
        // Capped below float32's overflow: an infinite dr would make bias * dr NaN at bias 0.
        dr = min(fg_conservative_dr(dr, bias, dr * k), 1e30);
        trap = min(trap, vec4(abs(z.x), abs(z.y), abs(z.z), r2));
    }
    // Knighty's pseudo-Kleinian seed: the disc z = 0 of radius sheet_radius (the second term is
    // about |z.z| away from the axis and vanishes on it, so the limit set's sheets stay thin).
    float rxy = sqrt(z.x * z.x + z.y * z.y);
    float seed = max(rxy - sheet_radius, abs(rxy * z.z) / max(length(z), FG_TINY));
    distance = seed / max(dr, FG_TINY);
}
