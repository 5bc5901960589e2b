void fg_math_divide(T a, T b, OUT(T) value)
{
    value = a / b;
}
