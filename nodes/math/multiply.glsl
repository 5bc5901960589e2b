void fg_math_multiply(T a, T b, OUT(T) value)
{
    value = a * b;
}
