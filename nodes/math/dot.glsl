void fg_math_dot(T a, T b, OUT(float) value)
{
    value = dot(a, b);
}
