void fg_trap_sphere(vec4 trap, float radius, float scale, OUT(float) value)
{
    value = scale * abs(sqrt(max(trap.w, 0.0)) - radius);
}
