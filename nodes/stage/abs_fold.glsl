void fg_stage_abs_fold(vec3 z, OUT(vec3) folded)
{
    folded = abs(z);
}

void fg_stage_abs_fold_tangent(vec3 z, vec3 d_z, OUT(vec3) d_folded)
{
    d_folded = d_z * (step(vec3(0.0), z) * 2.0 - 1.0);
}
