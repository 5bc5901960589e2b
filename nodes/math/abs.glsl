void fg_math_abs(T x, OUT(T) value)
{
    value = abs(x);
}
