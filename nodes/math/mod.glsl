void fg_math_mod(T x, float y, OUT(T) value)
{
    float py = max(y, FG_TINY);
    value = x - T(py) * floor(x / py);
}
