void fg_math_floor(T x, OUT(T) value)
{
    value = floor(x);
}
