void fg_stage_scale_axes(vec3 z, vec3 scale, OUT(vec3) scaled, OUT(float) gain)
{
    scaled = z * scale;
    vec3 a = abs(scale);
    gain = max(a.x, max(a.y, a.z));
}
