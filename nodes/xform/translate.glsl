void fg_xform_translate(vec3 p, vec3 offset, OUT(vec3) p_out)
{
    p_out = p - offset;
}
