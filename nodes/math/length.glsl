void fg_math_length(T v, OUT(float) value)
{
    value = length(v);
}
