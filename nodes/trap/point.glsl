void fg_trap_point(vec4 trap, float scale, OUT(float) value)
{
    value = scale * sqrt(max(trap.w, 0.0));
}
