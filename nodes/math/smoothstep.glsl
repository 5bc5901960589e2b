void fg_math_smoothstep(float edge0, float edge1, T x, OUT(T) value)
{
    value = smoothstep(T(edge0), T(edge1), x);
}

void fg_math_smoothstep_tangent(float edge0, float edge1, T x, T d_x, OUT(T) d_value)
{
    float width = edge1 - edge0;
    T t = clamp((x - T(edge0)) / width, T(0.0), T(1.0));
    d_value = 6.0 * t * (T(1.0) - t) / width * d_x;
}
