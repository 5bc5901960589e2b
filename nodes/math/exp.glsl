void fg_math_exp(T x, OUT(T) value)
{
    value = exp(min(x, T(80.0)));
}
