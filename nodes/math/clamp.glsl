void fg_math_clamp(T x, float lo, float hi, OUT(T) value)
{
    value = clamp(x, T(lo), T(hi));
}
