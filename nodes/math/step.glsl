void fg_math_step(float edge, T x, OUT(T) value)
{
    value = step(T(edge), x);
}
