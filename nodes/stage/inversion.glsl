void fg_stage_inversion(vec3 z, float radius2, OUT(vec3) inverted, OUT(float) gain)
{
    // A squared radius with a floor: the inversion divides by it.
    gain = max(radius2 / max(dot(z, z), 1e-12), 1.0);
    inverted = z * gain;
}

void fg_stage_inversion_tangent(vec3 z, float radius2, vec3 d_z, OUT(vec3) d_inverted)
{
    float r2 = max(dot(z, z), 1e-12);
    float gain = radius2 / r2;
    d_inverted = gain > 1.0 ? gain * (d_z - 2.0 * z * dot(z, d_z) / r2) : d_z;
}
