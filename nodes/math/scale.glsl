void fg_math_scale(T v, float s, OUT(T) value)
{
    value = v * s;
}
