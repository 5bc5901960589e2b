void fg_math_fract(T x, OUT(T) value)
{
    value = x - floor(x);
}
