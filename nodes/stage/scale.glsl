void fg_stage_scale(T z, float scale, OUT(T) scaled, OUT(float) gain)
{
    scaled = z * scale;
    gain = abs(scale);
}
