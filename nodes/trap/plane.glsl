void fg_trap_plane(vec4 trap, vec3 weights, float scale, OUT(float) value)
{
    vec3 w = max(weights, vec3(0.0));
    float total = w.x + w.y + w.z;
    value = scale * (w.x * trap.x + w.y * trap.y + w.z * trap.z) / max(total, FG_TINY);
}
