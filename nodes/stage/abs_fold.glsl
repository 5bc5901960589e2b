void fg_stage_abs_fold(vec3 z, OUT(vec3) folded)
{
    folded = abs(z);
}
