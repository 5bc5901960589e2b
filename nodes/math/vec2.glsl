void fg_math_vec2(float x, float y, OUT(vec2) value)
{
    value = vec2(x, y);
}

void fg_math_vec2_tangent(float x, float y, float d_x, float d_y, OUT(vec2) d_value)
{
    d_value = vec2(d_x, d_y);
}
