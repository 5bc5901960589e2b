void fg_math_pow(T x, float e, OUT(T) value)
{
    value = pow(max(x, T(0.0)), T(e));
}
