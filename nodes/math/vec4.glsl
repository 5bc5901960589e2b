void fg_math_vec4(float x, float y, float z, float w, OUT(vec4) value)
{
    value = vec4(x, y, z, w);
}
