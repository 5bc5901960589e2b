void fg_stage_inversion(vec3 z, float radius2, OUT(vec3) inverted, OUT(float) gain)
{
    // A squared radius with a floor: the inversion divides by it.
    gain = max(radius2 / max(dot(z, z), 1e-12), 1.0);
    inverted = z * gain;
}
