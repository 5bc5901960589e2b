void fg_math_dot(T a, T b, OUT(float) value)
{
    value = dot(a, b);
}

void fg_math_dot_tangent(T a, T b, T d_a, T d_b, OUT(float) d_value)
{
    d_value = dot(d_a, b) + dot(a, d_b);
}
