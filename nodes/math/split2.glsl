void fg_math_split2(vec2 v, OUT(float) x, OUT(float) y)
{
    x = v.x;
    y = v.y;
}

void fg_math_split2_tangent(vec2 v, vec2 d_v, OUT(float) d_x, OUT(float) d_y)
{
    d_x = d_v.x;
    d_y = d_v.y;
}
