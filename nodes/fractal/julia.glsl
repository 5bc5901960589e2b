void fg_fractal_julia(vec3 p, vec4 c, float slice_w, int iterations, float bailout, float bias,
                      OUT(float) distance, OUT(vec4) trap, OUT(float) escape)
{
    // The quaternion z = x + y i + z j + w k, with the real part in x.
    vec4 z = vec4(p.x, p.y, p.z, slice_w);
    float dr = 1.0;
    float r2 = dot(z, z);
    float bail2 = bailout * bailout;
    trap = vec4(abs(z.x), abs(z.y), abs(z.z), r2);
    float r2_last = r2;
    int i = 0;
    for (; i < iterations; i++) {
        fg_count_fractal_iteration();
        if (r2 > bail2) break;
        r2_last = r2;
        // z^2 = (x^2 - |v|^2, 2 x v); its derivative grows by 2 |z|.
        // Capped below float32's overflow: an infinite dr would make bias * dr NaN at bias 0.
        dr = min(fg_conservative_dr(dr, bias, 2.0 * sqrt(r2) * dr), 1e30);
        z = vec4(z.x * z.x - z.y * z.y - z.z * z.z - z.w * z.w, 2.0 * z.x * z.y, 2.0 * z.x * z.z, 2.0 * z.x * z.w) + c;
        r2 = dot(z, z);
        trap = min(trap, vec4(abs(z.x), abs(z.y), abs(z.z), r2));
    }
    // 0.5 log(r) r / dr; at r = 0 (and dr = 0 at a critical point) the maxes keep it finite.
    float r = sqrt(r2);
    distance = 0.5 * log(max(r, FG_TINY)) * r / max(dr, FG_TINY);
    escape = fg_escape_share(i, iterations, r2_last, r2, bail2);
    // Far away the estimate grows like r log r, faster than the true distance. Every orbit that
    // leaves |z| = R = max(2, |c|) escapes, so the set lies inside that ball and |p| - R bounds the
    // distance from below. Beyond 2 R the smaller of the two never oversteps; nearer in the cap
    // would put a false surface on the ball, and the estimate is good there.
    float ball = max(2.0, length(c));
    float reach = length(p) - ball;
    if (reach > ball) distance = min(distance, reach);
}
