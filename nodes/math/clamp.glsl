void fg_math_clamp(T x, float lo, float hi, OUT(T) value)
{
    value = clamp(x, T(lo), T(hi));
}

void fg_math_clamp_tangent(T x, float lo, float hi, T d_x, float d_lo, float d_hi, OUT(T) d_value)
{
    T below = T(1.0) - step(T(lo), x);
    T above = T(1.0) - step(x, T(hi));
    d_value = d_x * (T(1.0) - below - above) + d_lo * below + d_hi * above;
}
