void fg_stage_sphere_fold(vec3 z, float min_radius, float fixed_radius, OUT(vec3) folded, OUT(float) gain)
{
    // Squared radii with a floor: the fold divides by them.
    float min_r2 = max(min_radius * min_radius, 1e-12);
    float fixed_r2 = max(fixed_radius * fixed_radius, min_r2);
    float r2 = dot(z, z);
    gain = 1.0;
    if (r2 < min_r2) gain = fixed_r2 / min_r2;
    else if (r2 < fixed_r2) gain = fixed_r2 / r2;
    folded = z * gain;
}

void fg_stage_sphere_fold_tangent(vec3 z, float min_radius, float fixed_radius, vec3 d_z, OUT(vec3) d_folded)
{
    float min_r2 = max(min_radius * min_radius, 1e-12);
    float fixed_r2 = max(fixed_radius * fixed_radius, min_r2);
    float r2 = dot(z, z);
    // Inside the small sphere a uniform scale; between the spheres an inversion; outside, nothing.
    d_folded = r2 < min_r2     ? d_z * (fixed_r2 / min_r2)
               : r2 < fixed_r2 ? (fixed_r2 / r2) * (d_z - 2.0 * z * dot(z, d_z) / r2)
                               : d_z;
}
