void fg_math_sin(T x, OUT(T) value)
{
    value = sin(x);
}

void fg_math_sin_tangent(T x, T d_x, OUT(T) d_value)
{
    d_value = cos(x) * d_x;
}
