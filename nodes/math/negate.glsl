void fg_math_negate(T x, OUT(T) value)
{
    value = -x;
}

void fg_math_negate_tangent(T x, T d_x, OUT(T) d_value)
{
    d_value = -d_x;
}
