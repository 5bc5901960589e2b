void fg_stage_add_c(vec3 z, vec3 c, float weight, OUT(vec3) added)
{
    added = z + c * weight;
}
