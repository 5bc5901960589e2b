void fg_math_max(T a, T b, OUT(T) value)
{
    value = max(a, b);
}
