void fg_fractal_mandelbulb(vec3 p, float power, int iterations, float bailout, float bias,
                           OUT(float) distance, OUT(vec4) trap)
{
    vec3 z = p;
    float dr = 1.0;
    float r = length(z);
    trap = vec4(abs(z.x), abs(z.y), abs(z.z), r * r);
    for (int i = 0; i < iterations; i++) {
        if (r > bailout) break;
        // At the origin and on the y axis the angles are 0/0: the safe forms answer 0.
        float theta = fg_safe_acos(fg_safe_div(z.y, r)) * power;
        float phi = fg_safe_atan(z.x, z.z) * power;
        dr = fg_conservative_dr(dr, bias, power * pow(max(r, FG_TINY), power - 1.0) * dr + 1.0);
        float zr = pow(max(r, FG_TINY), power);
        z = p + zr * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
        r = length(z);
        trap = min(trap, vec4(abs(z.x), abs(z.y), abs(z.z), r * r));
    }
    // log(r) * r tends to 0 at r = 0: the max keeps log finite there.
    distance = 0.5 * log(max(r, FG_TINY)) * r / dr;
}
