void fg_math_atan2(float y, float x, OUT(float) value)
{
    value = fg_safe_atan(y, x);
}
