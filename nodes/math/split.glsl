void fg_math_split(vec3 v, OUT(float) x, OUT(float) y, OUT(float) z)
{
    x = v.x;
    y = v.y;
    z = v.z;
}

void fg_math_split_tangent(vec3 v, vec3 d_v, OUT(float) d_x, OUT(float) d_y, OUT(float) d_z)
{
    d_x = d_v.x;
    d_y = d_v.y;
    d_z = d_v.z;
}
