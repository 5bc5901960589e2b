void fg_math_normalize(T v, OUT(T) value)
{
    float len = length(v);
    value = len > FG_TINY ? v / len : v * 0.0;
}
