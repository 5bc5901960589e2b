void fg_stage_translate(vec3 z, vec3 offset, OUT(vec3) moved)
{
    moved = z + offset;
}
