void fg_math_negate(T x, OUT(T) value)
{
    value = -x;
}
