void fg_fractal_mandelbulb(vec3 p, float power, int iterations, float bailout, float bias,
                           OUT(float) distance, OUT(vec4) trap, OUT(float) escape)
{
    vec3 z = p;
    float dr = 1.0;
    float r = length(z);
    trap = vec4(abs(z.x), abs(z.y), abs(z.z), r * r);
    float r_last = r;
    int i = 0;
    for (; i < iterations; i++) {
        fg_count_fractal_iteration();
        // An orbit whose next radius would pass FG_RADIUS_MAX escapes in the next step anyway, and
        // the estimate is (nearly) the same one step earlier: stop before float overflows.
        float zr = pow(max(r, FG_TINY), power);
        if (r > bailout || zr > FG_RADIUS_MAX) break;
        // At the origin and on the y axis the angles are 0/0: the safe forms answer 0.
        float theta = fg_safe_acos(fg_safe_div(z.y, r)) * power;
        float phi = fg_safe_atan(z.x, z.z) * power;
        dr = fg_conservative_dr(dr, bias, fg_grow_dr(dr, power * pow(max(r, FG_TINY), power - 1.0)));
        z = p + zr * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
        r_last = r;
        r = length(z);
        trap = min(trap, vec4(abs(z.x), abs(z.y), abs(z.z), r * r));
    }
    // log(r) * r tends to 0 at r = 0: the max keeps log finite there.
    distance = 0.5 * log(max(r, FG_TINY)) * r / dr;
    escape = fg_escape_share(i, iterations, r_last * r_last, r * r, bailout * bailout);
    // Far away the estimate grows like r log r, faster than the true distance. Orbits that leave
    // |z| = 2 escape (for power >= 2), so the bulb lies inside that ball and |p| - 2 bounds the
    // distance from below. Beyond twice that radius the smaller of the two never oversteps; nearer
    // in the cap would put a false surface on the ball, and the estimate is good there.
    float reach = length(p) - 2.0;
    if (reach > 2.0) distance = min(distance, reach);
}
