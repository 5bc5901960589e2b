void fg_math_sin(T x, OUT(T) value)
{
    value = sin(x);
}
