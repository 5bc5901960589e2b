void fg_math_sign(T x, OUT(T) value)
{
    value = sign(x);
}
