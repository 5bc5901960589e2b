void fg_fractal_apollonian(vec3 p, float size, float inversion, float thickness, int iterations, float bias,
                           OUT(float) distance, OUT(vec4) trap)
{
    float s = max(size, 1e-6);
    vec3 z = p / s;
    float dr = 1.0;
    trap = vec4(1e4);
    for (int i = 0; i < iterations; i++) {
        fg_count_fractal_iteration();
        // Fold into the unit cell [-1, 1]^3, then invert in the sphere of squared radius `inversion`.
        z = 2.0 * fract(0.5 * z + vec3(0.5)) - vec3(1.0);
        float r2 = max(dot(z, z), 1e-12);
        float k = inversion / r2;
        z = z * k;
        // Capped below float32's overflow: an infinite dr would make bias * dr NaN at bias 0.
        dr = min(fg_conservative_dr(dr, bias, dr * k), 1e30);
        trap = min(trap, vec4(abs(z.x), abs(z.y), abs(z.z), r2));
    }
    // The packing is the limit of the sheet |y| < thickness; 0.25 keeps the estimate under the true distance.
    distance = 0.25 * (abs(z.y) - thickness) / max(dr, FG_TINY) * s;
}
