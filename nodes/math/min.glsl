void fg_math_min(T a, T b, OUT(T) value)
{
    value = min(a, b);
}
