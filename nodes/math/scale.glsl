void fg_math_scale(T v, float s, OUT(T) value)
{
    value = v * s;
}

void fg_math_scale_tangent(T v, float s, T d_v, float d_s, OUT(T) d_value)
{
    d_value = d_v * s + v * d_s;
}
