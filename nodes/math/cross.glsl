void fg_math_cross(vec3 a, vec3 b, OUT(vec3) value)
{
    value = cross(a, b);
}

void fg_math_cross_tangent(vec3 a, vec3 b, vec3 d_a, vec3 d_b, OUT(vec3) d_value)
{
    d_value = cross(d_a, b) + cross(a, d_b);
}
