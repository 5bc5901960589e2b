void fg_math_split4(vec4 v, OUT(float) x, OUT(float) y, OUT(float) z, OUT(float) w)
{
    x = v.x;
    y = v.y;
    z = v.z;
    w = v.w;
}
