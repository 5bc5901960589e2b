void fg_math_sqrt(T x, OUT(T) value)
{
    value = sqrt(max(x, T(0.0)));
}
