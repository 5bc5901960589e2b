void fg_math_atan2(float y, float x, OUT(float) value)
{
    value = fg_safe_atan(y, x);
}

void fg_math_atan2_tangent(float y, float x, float d_y, float d_x, OUT(float) d_value)
{
    d_value = fg_safe_div(x * d_y - y * d_x, x * x + y * y);
}
