void fg_math_add(T a, T b, OUT(T) value)
{
    value = a + b;
}
