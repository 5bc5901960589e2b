void fg_math_multiply(T a, T b, OUT(T) value)
{
    value = a * b;
}

void fg_math_multiply_tangent(T a, T b, T d_a, T d_b, OUT(T) d_value)
{
    d_value = d_a * b + a * d_b;
}
