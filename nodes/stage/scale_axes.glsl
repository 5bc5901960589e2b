void fg_stage_scale_axes(vec3 z, vec3 scale, OUT(vec3) scaled, OUT(float) gain)
{
    scaled = z * scale;
    vec3 a = abs(scale);
    gain = max(a.x, max(a.y, a.z));
}

void fg_stage_scale_axes_tangent(vec3 z, vec3 scale, vec3 d_z, OUT(vec3) d_scaled)
{
    d_scaled = d_z * scale;
}
