void fg_stage_scale(vec3 z, float scale, OUT(vec3) scaled, OUT(float) gain)
{
    scaled = z * scale;
    gain = abs(scale);
}
