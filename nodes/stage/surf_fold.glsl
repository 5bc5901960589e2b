void fg_stage_surf_fold(vec3 z, float fold_x, float fold_y, OUT(vec3) folded)
{
    folded = vec3(clamp(z.x, -fold_x, fold_x) * 2.0 - z.x, clamp(z.y, -fold_y, fold_y) * 2.0 - z.y, z.z);
}

void fg_stage_surf_fold_tangent(vec3 z, float fold_x, float fold_y, vec3 d_z, OUT(vec3) d_folded)
{
    float keep_x = step(-fold_x, z.x) * step(z.x, fold_x) * 2.0 - 1.0;
    float keep_y = step(-fold_y, z.y) * step(z.y, fold_y) * 2.0 - 1.0;
    d_folded = vec3(d_z.x * keep_x, d_z.y * keep_y, d_z.z);
}
