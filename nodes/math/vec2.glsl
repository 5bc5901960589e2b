void fg_math_vec2(float x, float y, OUT(vec2) value)
{
    value = vec2(x, y);
}
