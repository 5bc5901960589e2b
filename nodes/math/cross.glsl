void fg_math_cross(vec3 a, vec3 b, OUT(vec3) value)
{
    value = cross(a, b);
}
