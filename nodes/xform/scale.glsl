void fg_xform_scale(vec3 p, float s, OUT(vec3) p_out)
{
    p_out = p / max(s, FG_TINY);
}
