void fg_stage_menger_scale(vec3 z, float scale, vec3 offset, OUT(vec3) scaled, OUT(float) gain)
{
    scaled = z * scale - offset * (scale - 1.0);
    if (scaled.z < -0.5 * offset.z * (scale - 1.0)) scaled.z += offset.z * (scale - 1.0);
    gain = abs(scale);
}

void fg_stage_menger_scale_tangent(vec3 z, float scale, vec3 offset, vec3 d_z, OUT(vec3) d_scaled)
{
    d_scaled = d_z * scale;
}
