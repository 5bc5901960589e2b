void fg_stage_surf_fold(vec3 z, float fold_x, float fold_y, OUT(vec3) folded)
{
    folded = vec3(clamp(z.x, -fold_x, fold_x) * 2.0 - z.x, clamp(z.y, -fold_y, fold_y) * 2.0 - z.y, z.z);
}
