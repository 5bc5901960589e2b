void fg_math_length(T v, OUT(float) value)
{
    value = length(v);
}

void fg_math_length_tangent(T v, T d_v, OUT(float) d_value)
{
    float len = length(v);
    // At the origin every direction stretches by its own length.
    d_value = len > FG_TINY ? dot(v, d_v) / len : length(d_v);
}
