void fg_math_normalize(T v, OUT(T) value)
{
    float len = length(v);
    value = len > FG_TINY ? v / len : v * 0.0;
}

void fg_math_normalize_tangent(T v, T d_v, OUT(T) d_value)
{
    float len = length(v);
    T n = len > FG_TINY ? v / len : v * 0.0;
    d_value = len > FG_TINY ? (d_v - n * dot(n, d_v)) / len : v * 0.0;
}
