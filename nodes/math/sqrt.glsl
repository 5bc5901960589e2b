void fg_math_sqrt(T x, OUT(T) value)
{
    value = sqrt(max(x, T(0.0)));
}

void fg_math_sqrt_tangent(T x, T d_x, OUT(T) d_value)
{
    // Steep near 0: the floor keeps the slope finite, a bound the guard then caps.
    d_value = step(T(0.0), x) * 0.5 * d_x / max(sqrt(max(x, T(0.0))), T(1e-12));
}
