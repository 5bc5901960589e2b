void fg_math_split4(vec4 v, OUT(float) x, OUT(float) y, OUT(float) z, OUT(float) w)
{
    x = v.x;
    y = v.y;
    z = v.z;
    w = v.w;
}

void fg_math_split4_tangent(vec4 v, vec4 d_v, OUT(float) d_x, OUT(float) d_y, OUT(float) d_z, OUT(float) d_w)
{
    d_x = d_v.x;
    d_y = d_v.y;
    d_z = d_v.z;
    d_w = d_v.w;
}
