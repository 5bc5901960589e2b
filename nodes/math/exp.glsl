void fg_math_exp(T x, OUT(T) value)
{
    value = exp(min(x, T(80.0)));
}

void fg_math_exp_tangent(T x, T d_x, OUT(T) d_value)
{
    d_value = exp(min(x, T(80.0))) * step(x, T(80.0)) * d_x;
}
