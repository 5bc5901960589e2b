void fg_math_vec3(float x, float y, float z, OUT(vec3) value)
{
    value = vec3(x, y, z);
}

void fg_math_vec3_tangent(float x, float y, float z, float d_x, float d_y, float d_z, OUT(vec3) d_value)
{
    d_value = vec3(d_x, d_y, d_z);
}
