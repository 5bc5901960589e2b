void fg_math_split2(vec2 v, OUT(float) x, OUT(float) y)
{
    x = v.x;
    y = v.y;
}
