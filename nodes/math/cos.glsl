void fg_math_cos(T x, OUT(T) value)
{
    value = cos(x);
}
