// Helpers shared by every node body. Compiled as GLSL for the GPU and as C++ (double precision)
// for the CPU twin, so keep to the common subset: no swizzles beyond .x/.y/.z/.w, no 'f' suffixes.

const float FG_PI = 3.14159265358979;
const float FG_TINY = 1e-20;
// Fractal loops call fg_count_fractal_iteration() once per iteration: marching passes count them in
// their counting frame (march_counters.glsl); everywhere else, and in the CPU twin, it is nothing.
#ifndef FG_COUNTS_FRACTAL_ITERATIONS
#define fg_count_fractal_iteration()
#endif

// Cap of a running derivative. At high iteration counts dr grows past float's 3.4e38 (16^64 for a
// power-16 bulb); capped here, with a bias up to 4 it stays finite, and a distance r log r / dr
// with r below FG_RADIUS_MAX is below 1e-17 anyway.
const float FG_DR_MAX = 1e37;
// Largest orbit radius a fractal iterates on: its square must stay finite in float for length().
const float FG_RADIUS_MAX = 1e18;

// The conservative running derivative (Framestore): never let the derivative shrink below
// bias * its previous value, so the distance estimate cannot overshoot where the plain formula
// underestimates the growth. bias = 0 turns the guard off.
float fg_conservative_dr(float dr, float bias, float next)
{
    return min(max(dr * bias, next), FG_DR_MAX);
}

// Shirley and Chiu's concentric map of the unit square onto the unit disc: it keeps points that
// cover the square evenly spread over the disc.
vec2 fg_concentric_disc(vec2 square)
{
    vec2 u = 2.0 * square - 1.0;
    if (u.x == 0.0 && u.y == 0.0) return vec2(0.0);
    const float quarter = 0.785398163;
    bool wide = abs(u.x) > abs(u.y);
    float r = wide ? u.x : u.y;
    float phi = wide ? quarter * (u.y / u.x) : 2.0 * quarter - quarter * (u.x / u.y);
    return vec2(r * cos(phi), r * sin(phi));
}

// How far an orbit got before escaping (a fractal's escape output, for iteration fog): `done`
// iterations ran before |z|^2 passed bail2, the last one counted by its share of the way there from
// r2_last in log |z|, so that the count runs on across the iteration bands. The maximum where the
// orbit never escaped, 0 where it starts outside.
float fg_escape_share(int done, int iterations, float r2_last, float r2, float bail2)
{
    if (r2 <= bail2) return float(iterations);
    if (done == 0) return 0.0;
    return float(done - 1) + clamp(log(bail2 / r2_last) / max(log(r2 / r2_last), FG_TINY), 0.0, 1.0);
}

// The plain running derivative gain * dr + 1, computed so that it never overflows: it stops at
// FG_DR_MAX, where the distance is already negligible.
float fg_grow_dr(float dr, float gain)
{
    return gain * min(dr, FG_DR_MAX / max(gain, 1.0)) + 1.0;
}

// A running derivative times a formula stage's factor without overflowing, and without a division
// (one per stage made formula graphs 40 % slower than hand-written nodes on lavapipe): exact while
// both are below 1e18, where the product stays below FG_DR_MAX; past that the distance is below
// 1e-18 of the orbit's radius, and FG_DR_MAX makes it smaller still, never larger.
float fg_scale_dr(float dr, float factor)
{
    return dr < 1e18 && factor < 1e18 ? dr * factor : FG_DR_MAX;
}

// acos that stays defined when rounding pushes its argument past +-1.
float fg_safe_acos(float x)
{
    return acos(clamp(x, -1.0, 1.0));
}

// atan2 that answers 0 at the origin instead of an undefined value.
float fg_safe_atan(float y, float x)
{
    if (abs(x) < FG_TINY && abs(y) < FG_TINY) return 0.0;
    return atan(y, x);
}

// Division by a length that may be zero.
float fg_safe_div(float a, float b)
{
    return a / max(b, FG_TINY);
}

// Rotation of p about a unit axis by an angle (Rodrigues).
vec3 fg_rotate_axis(vec3 p, vec3 axis, float angle)
{
    float c = cos(angle);
    float s = sin(angle);
    return p * c + cross(axis, p) * s + axis * (dot(axis, p) * (1.0 - c));
}

// Fresnel's reflectance of a smooth boundary into a medium eta times as dense (eta = n_t / n_i), both
// polarisations averaged, at the cosine cos_i of the angle of incidence: 1 past the critical angle.
float fg_fresnel_dielectric(float cos_i, float eta)
{
    float c = clamp(cos_i, 0.0, 1.0);
    float sin_t2 = (1.0 - c * c) / (eta * eta);
    if (sin_t2 >= 1.0) return 1.0;
    float cos_t = sqrt(1.0 - sin_t2);
    float rs = (c - eta * cos_t) / max(c + eta * cos_t, 1e-12);
    float rp = (cos_t - eta * c) / max(cos_t + eta * c, 1e-12);
    return 0.5 * (rs * rs + rp * rp);
}

// iq's gain: a symmetric contrast curve used by the one-sample lighting tricks.
float fg_gain(float x, float k)
{
    float xc = clamp(x, 0.0, 1.0);
    float a = 0.5 * pow(2.0 * (xc < 0.5 ? xc : 1.0 - xc), k);
    return xc < 0.5 ? a : 1.0 - a;
}
