void fg_math_vec4(float x, float y, float z, float w, OUT(vec4) value)
{
    value = vec4(x, y, z, w);
}

void fg_math_vec4_tangent(float x, float y, float z, float w, float d_x, float d_y, float d_z, float d_w,
                        OUT(vec4) d_value)
{
    d_value = vec4(d_x, d_y, d_z, d_w);
}
