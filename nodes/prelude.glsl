// Helpers shared by every node body. Compiled as GLSL for the GPU and as C++ (double precision)
// for the CPU twin, so keep to the common subset: no swizzles beyond .x/.y/.z/.w, no 'f' suffixes.

const float FG_PI = 3.14159265358979;
const float FG_TINY = 1e-20;

// The conservative running derivative (Framestore): never let the derivative shrink below
// bias * its previous value, so the distance estimate cannot overshoot where the plain formula
// underestimates the growth. bias = 0 turns the guard off.
float fg_conservative_dr(float dr, float bias, float next)
{
    return max(dr * bias, next);
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

// iq's gain: a symmetric contrast curve used by the one-sample lighting tricks.
float fg_gain(float x, float k)
{
    float xc = clamp(x, 0.0, 1.0);
    float a = 0.5 * pow(2.0 * (xc < 0.5 ? xc : 1.0 - xc), k);
    return xc < 0.5 ? a : 1.0 - a;
}
