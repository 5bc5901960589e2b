void fg_stage_box_fold(vec3 z, vec3 limit, OUT(vec3) folded)
{
    folded = clamp(z, -limit, limit) * 2.0 - z;
}
