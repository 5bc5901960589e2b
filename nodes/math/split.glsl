void fg_math_split(vec3 v, OUT(float) x, OUT(float) y, OUT(float) z)
{
    x = v.x;
    y = v.y;
    z = v.z;
}
