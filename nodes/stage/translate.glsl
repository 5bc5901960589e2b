void fg_stage_translate(vec3 z, vec3 offset, OUT(vec3) moved)
{
    moved = z + offset;
}

void fg_stage_translate_tangent(vec3 z, vec3 offset, vec3 d_z, OUT(vec3) d_moved)
{
    d_moved = d_z;
}
