void fg_math_mix(T a, T b, float t, OUT(T) value)
{
    value = mix(a, b, t);
}

void fg_math_mix_tangent(T a, T b, float t, T d_a, T d_b, float d_t, OUT(T) d_value)
{
    d_value = d_a * (1.0 - t) + d_b * t + (b - a) * d_t;
}
