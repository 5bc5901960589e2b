void fg_math_abs(T x, OUT(T) value)
{
    value = abs(x);
}

void fg_math_abs_tangent(T x, T d_x, OUT(T) d_value)
{
    // The crease at 0 takes the slope of its positive side, so no direction is lost there.
    d_value = d_x * (step(T(0.0), x) * 2.0 - 1.0);
}
