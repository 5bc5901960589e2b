void fg_prim_capsule(vec3 p, vec3 a, vec3 b, float radius, OUT(float) distance)
{
    vec3 pa = p - a;
    vec3 ba = b - a;
    // A degenerate segment (a == b) divides by zero: the max turns it into a sphere.
    float h = clamp(dot(pa, ba) / max(dot(ba, ba), FG_TINY), 0.0, 1.0);
    distance = length(pa - ba * h) - radius;
}
