void fg_math_cos(T x, OUT(T) value)
{
    value = cos(x);
}

void fg_math_cos_tangent(T x, T d_x, OUT(T) d_value)
{
    d_value = -sin(x) * d_x;
}
