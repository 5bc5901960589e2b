void fg_stage_box_fold(vec3 z, vec3 limit, OUT(vec3) folded)
{
    folded = clamp(z, -limit, limit) * 2.0 - z;
}

void fg_stage_box_fold_tangent(vec3 z, vec3 limit, vec3 d_z, OUT(vec3) d_folded)
{
    // Inside the box z is kept, outside it is mirrored.
    vec3 inside = step(-limit, z) * step(z, limit);
    d_folded = d_z * (inside * 2.0 - 1.0);
}
