void fg_math_pow(T x, float e, OUT(T) value)
{
    // GLSL leaves pow(0, 0) undefined: the base never reaches 0.
    value = pow(max(x, T(FG_TINY)), T(e));
}
