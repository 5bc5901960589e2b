void fg_math_vec3(float x, float y, float z, OUT(vec3) value)
{
    value = vec3(x, y, z);
}
