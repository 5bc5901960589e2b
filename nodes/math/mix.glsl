void fg_math_mix(T a, T b, float t, OUT(T) value)
{
    value = mix(a, b, t);
}
