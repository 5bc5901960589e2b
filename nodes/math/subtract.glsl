void fg_math_subtract(T a, T b, OUT(T) value)
{
    value = a - b;
}
