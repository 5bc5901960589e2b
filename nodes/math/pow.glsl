void fg_math_pow(T x, float e, OUT(T) value)
{
    // GLSL leaves pow(0, 0) undefined: the base never reaches 0.
    value = pow(max(x, T(FG_TINY)), T(e));
}

void fg_math_pow_tangent(T x, float e, T d_x, float d_e, OUT(T) d_value)
{
    T base = max(x, T(FG_TINY));
    d_value = e * pow(base, T(e - 1.0)) * step(T(FG_TINY), x) * d_x + pow(base, T(e)) * log(base) * d_e;
}
