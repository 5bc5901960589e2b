void fg_math_min(T a, T b, OUT(T) value)
{
    value = min(a, b);
}

void fg_math_min_tangent(T a, T b, T d_a, T d_b, OUT(T) d_value)
{
    d_value = d_b + (d_a - d_b) * step(a, b);
}
