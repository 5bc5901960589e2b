void fg_math_max(T a, T b, OUT(T) value)
{
    value = max(a, b);
}

void fg_math_max_tangent(T a, T b, T d_a, T d_b, OUT(T) d_value)
{
    d_value = d_b + (d_a - d_b) * step(b, a);
}
