void fg_math_smoothstep(float edge0, float edge1, T x, OUT(T) value)
{
    value = smoothstep(T(edge0), T(edge1), x);
}
