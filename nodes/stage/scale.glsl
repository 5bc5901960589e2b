void fg_stage_scale(T z, float scale, OUT(T) scaled, OUT(float) gain)
{
    scaled = z * scale;
    gain = abs(scale);
}

void fg_stage_scale_tangent(T z, float scale, T d_z, OUT(T) d_scaled)
{
    d_scaled = d_z * scale;
}
